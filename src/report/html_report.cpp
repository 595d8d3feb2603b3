#include "report/html_report.hpp"

#include <filesystem>

#include "io/number_format.hpp"
#include "io/output_set.hpp"
#include "render/contact_sheet.hpp"
#include "render/image.hpp"
#include "report/html_escape.hpp"
#include "report/results_table.hpp"
#include "report/svg_chart.hpp"
#include "sim/scene_file.hpp"

namespace fragsim {
namespace {

constexpr const char* kSheetFile = "sheet.png";
constexpr const char* kTableFile = "table.csv";

// Kept in the page (no stylesheet to fetch). System fonts only.
constexpr const char* kStyle =
    R"(body { font-family: system-ui, -apple-system, "Segoe UI", Roboto, "DejaVu Sans", sans-serif;
  color: #222; background: #fff; margin: 0 auto; padding: 16px 16px 40px; max-width: 1320px;
  line-height: 1.45; }
h1 { font-size: 1.6em; margin: 0.4em 0 0.2em; }
h2 { font-size: 1.2em; margin: 1.6em 0 0.5em; border-bottom: 1px solid #ddd; padding-bottom: 0.2em; }
p.meta { color: #555; margin-top: 0; }
.reading p { max-width: 60em; }
.table-wrap { overflow-x: auto; }
table { border-collapse: collapse; font-size: 0.82em; font-variant-numeric: tabular-nums; }
th, td { padding: 3px 5px; border-bottom: 1px solid #e4e4e4; white-space: nowrap; }
th { background: #f3f3f3; text-align: right; font-weight: 600; vertical-align: bottom; }
th span { display: block; font-weight: normal; color: #666; }
td { text-align: right; }
th:first-child, td:first-child { text-align: left; }
tr.best td { background: #eaf6ee; font-weight: 600; }
.notes { font-size: 0.85em; color: #555; max-width: 70em; }
.charts { display: grid; grid-template-columns: repeat(auto-fill, minmax(520px, 1fr)); gap: 12px 24px; }
figure { margin: 0; }
svg.chart { width: 100%; height: auto; display: block; }
figcaption { font-size: 0.85em; color: #555; margin: 2px 0 8px; }
img.sheet { max-width: 100%; height: auto; display: block; border: 1px solid #ccc; }
pre { background: #f6f6f6; border: 1px solid #e2e2e2; padding: 10px 12px; overflow-x: auto;
  font-size: 0.85em; }
pre.ini { column-width: 26em; column-gap: 2em; }
pre.ini span { display: block; break-inside: avoid; }
.viewer-controls { display: flex; flex-wrap: wrap; align-items: center; gap: 6px 14px;
  margin: 6px 0; font-size: 0.9em; }
#viewer-time { flex: 1; min-width: 240px; }
#viewer { width: 100%; }
#viewer canvas { display: block; width: 100%; border: 1px solid #ccc; touch-action: none; }
footer { margin-top: 2em; font-size: 0.85em; color: #666; }
)";

std::string percent(double share) {
  return percent_text(share, 1);
}

std::string count(int n, const std::string& singular, const std::string& plural) {
  return std::to_string(n) + " " + (n == 1 ? singular : plural);
}

const Evaluation* find_run(const std::vector<Evaluation>& runs, const std::string& strategy) {
  for (const Evaluation& e : runs) {
    if (e.summary.strategy == strategy) return &e;
  }
  return nullptr;
}

bool has_occlusion(const Evaluation& e) {
  return !e.occlusion_per_step.empty();
}

// "a", "a and b", "a, b and c".
std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i > 0) out += i + 1 == items.size() ? " and " : ", ";
    out += items[i];
  }
  return out;
}

// The notes under the page's table, as HTML: the legend, what the page leaves out, then the
// runs' notes (the terminal's, less the timings).
std::vector<std::string> table_notes(const ResultsTable& table) {
  std::vector<std::string> notes{
      legend_html(table) +
      " The highlighted row met the thesis&#39;s goals with the least deviation. Timings are not "
      "on this page (it is the same bytes for the same scene and seed): the terminal report and "
      "--csv&#39;s timing.csv have them. The table as CSV: <a href=\"" +
      std::string(kTableFile) + "\">" + kTableFile + "</a>."};
  for (const ResultsNote& n : table.notes) {
    if (!n.timing) notes.push_back(html_escape(n.text) + ".");
  }
  return notes;
}

struct ChartSpec {
  LineChart chart;
  std::string caption;
};

// One chart per per-step series, a line per strategy; x is the time at the end of each step.
std::vector<ChartSpec> charts(const Scene& scene, const std::vector<Evaluation>& runs) {
  std::vector<double> t_s;
  const std::size_t steps = runs.empty() ? 0 : runs.front().near_per_step.size();
  for (std::size_t k = 0; k < steps; ++k)
    t_s.push_back(static_cast<double>(k + 1) * scene.sim.dt_s);
  const auto make = [&](const std::string& title, const std::string& y_label, auto value) {
    LineChart c;
    c.title = title;
    c.x_label = "t (s)";
    c.y_label = y_label;
    c.x = t_s;
    for (const Evaluation& e : runs) {
      ChartSeries s;
      s.name = e.summary.strategy;
      for (std::size_t k = 0; k < steps; ++k) s.y.push_back(value(e, k));
      c.series.push_back(std::move(s));
    }
    return c;
  };
  std::vector<ChartSpec> out;
  out.push_back({make("Near-plane intersections", "fragments",
                      [](const Evaluation& e, std::size_t k) {
                        return k < e.near_per_step.size() ? e.near_per_step[k] : 0.0;
                      }),
                 "Fragments meeting the near rectangle during each step (swept): what the "
                 "thesis's goals require to be zero."});
  out.push_back({make("Edge candidates", "candidates",
                      [](const Evaluation& e, std::size_t k) {
                        return k < e.candidates_per_step.size() ? e.candidates_per_step[k] : 0.0;
                      }),
                 "Fragments the strategy treats as candidates each step (edge, edge-min; zero "
                 "for the others)."});
  const bool occlusion = !runs.empty() && has_occlusion(runs.front());
  if (occlusion) {
    out.push_back({make("Screen occlusion", "screen covered (%)",
                        [](const Evaluation& e, std::size_t k) {
                          return k < e.occlusion_per_step.size() ? 100.0 * e.occlusion_per_step[k]
                                                                 : 0.0;
                        }),
                   "Share of the viewport covered by fragments each step."});
    out.push_back({make("Central occlusion", "central region covered (%)",
                        [](const Evaluation& e, std::size_t k) {
                          return k < e.central_occlusion_per_step.size()
                                     ? 100.0 * e.central_occlusion_per_step[k]
                                     : 0.0;
                        }),
                   "Share of the screen's central region covered each step: debris in front of "
                   "the lens hides what the player looks at."});
  }
  out.push_back({make("Near distance", "near plane distance (m)",
                      [](const Evaluation& e, std::size_t k) {
                        return k + 1 < e.camera.size() ? e.camera[k + 1].near_m : 0.0;
                      }),
                 "The near plane's distance from the eye each step (only near-plane moves it)."});
  return out;
}

std::string sheet_caption(const Scene& scene, const SheetFigure& sheet) {
  std::vector<std::string> times;
  for (const int step : sheet.steps) times.push_back(fixed_text(step * scene.sim.dt_s, 2));
  return "What the camera sees: a row per strategy, a column per time (t = " + joined(times) +
         " s), drawn from the same runs the table reports. Red outlines: the near plane's cut "
         "through a fragment (a hole a game would show).";
}

// The scene file's text, escaped, each blank-line-separated section in its own block so the
// settings' columns never split a section from its header.
std::string ini_sections(const std::string& ini) {
  std::string out;
  std::size_t start = 0;
  while (start < ini.size()) {
    std::size_t end = ini.find("\n\n", start);
    end = end == std::string::npos ? ini.size() : end + 2;
    out += "<span>" + html_escape(ini.substr(start, end - start)) + "</span>";
    start = end;
  }
  return out;
}

}  // namespace

std::vector<int> report_sheet_steps(const Scene& scene) {
  return default_sheet_steps(scene.step_count());
}

std::vector<std::string> report_reading(const std::vector<Evaluation>& runs) {
  std::vector<std::string> paragraphs;
  const Evaluation* none = find_run(runs, "none");
  if (none) {
    const RunSummary& s = none->summary;
    std::string p;
    if (thesis_goal_failures(s) == 0) {
      p = "Without control (none), no fragment met the near plane or the camera body on this "
          "scene.";
    } else {
      p = "Without control (none), " +
          count(s.intersections.near_fragments, "fragment", "fragments") + " met the near plane (" +
          count(s.intersections.near_fragment_steps, "fragment-step", "fragment-steps") + ") and " +
          std::to_string(s.intersections.camera_hit_fragments) + " hit the camera body.";
    }
    if (has_occlusion(*none)) {
      p += " The debris covered up to " + percent(s.occlusion.max) + "% of the screen and " +
           percent(s.occlusion.central_max) + "% of its central region.";
    }
    paragraphs.push_back(p);
  } else {
    paragraphs.push_back(
        "none was not among the compared strategies: there is no uncontrolled run on this page "
        "to set the numbers against (deviation is still measured from it).");
  }

  const std::optional<std::size_t> best = best_for_thesis_goals(runs);
  if (!best) {
    paragraphs.push_back(
        "Only none ran: there is no strategy to judge against the thesis's goals.");
    return paragraphs;
  }
  const Evaluation& b = runs[*best];
  const RunSummary& s = b.summary;
  if (thesis_goal_failures(s) > 0) {
    std::string p =
        "No strategy met the thesis's goals on this scene (no near-plane intersections, no "
        "camera hits and no fragment vanishing on screen): each let fragments through or made "
        "them disappear. The closest, " +
        s.strategy + ": " +
        count(s.intersections.near_fragments, "near-plane intersection",
              "near-plane intersections") +
        ", " + count(s.intersections.camera_hit_fragments, "camera hit", "camera hits");
    if (s.intersections.vanished_fragments > 0) {
      p += ", " + count(s.intersections.vanished_fragments, "fragment", "fragments") + " vanished";
    }
    if (b.has_deviation) p += ", mean deviation " + fixed_text(s.deviation.mean_m, 3) + " m";
    paragraphs.push_back(p + ".");
    return paragraphs;
  }
  const bool alone = runs.size() - (none ? 1 : 0) == 1;
  std::string p = s.strategy +
                  (alone ? " met the thesis's goals (no near-plane intersections, camera hits "
                           "or vanished fragments)"
                         : " met the thesis's goals best (no near-plane intersections, camera "
                           "hits or vanished fragments, then the least deviation)") +
                  ": 0 near-plane intersections, 0 camera hits";
  if (b.has_deviation) {
    p += ", mean deviation " + fixed_text(s.deviation.mean_m, 3) + " m (" +
         percent(s.deviation.deviated_share) +
         "% of the fragments moved more than 1 cm, the most by " +
         fixed_text(s.deviation.max_m, 3) + " m)";
  }
  p += ", " + count(s.intersections.near_misses, "near miss", "near misses") + ".";
  if (has_occlusion(b)) {
    p += " Occlusion of the central region: up to " + percent(s.occlusion.central_max) +
         "% (mean " + percent(s.occlusion.central_mean) + "%)";
    if (none && has_occlusion(*none)) {
      p += " against " + percent(none->summary.occlusion.central_max) + "% (mean " +
           percent(none->summary.occlusion.central_mean) + "%) without control";
    }
    p += "; of the whole screen, mean " + percent(s.occlusion.mean) + "%";
    if (none && has_occlusion(*none)) {
      p += " against " + percent(none->summary.occlusion.mean) + "%";
    }
    p += ".";
  } else {
    p += " Occlusion was not measured (--no-occlusion).";
  }
  paragraphs.push_back(p);

  std::vector<std::string> also;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const RunSummary& o = runs[i].summary;
    if (i == *best || o.strategy == "none" || thesis_goal_failures(o) > 0) continue;
    also.push_back(o.strategy +
                   (runs[i].has_deviation
                        ? " (mean deviation " + fixed_text(o.deviation.mean_m, 3) + " m)"
                        : std::string()));
  }
  if (!also.empty()) {
    paragraphs.push_back(
        "Also free of intersections and camera hits, with more deviation: " + joined(also) + ".");
  }
  // For a run that hides debris rather than steer it, what it saves at the lens and costs.
  for (const Evaluation& e : runs) {
    const RunSummary& o = e.summary;
    if (o.intersections.vanished_fragments == 0) continue;
    std::string v =
        o.strategy + " made " + count(o.intersections.vanished_fragments, "fragment", "fragments") +
        " vanish in view (faded below half opacity, or invisible at the near plane), "
        "the debris that \"suddenly disappears\" the thesis sets out to avoid: it "
        "counts as a failure of the goals, as a cut does. It left " +
        count(o.intersections.near_fragments, "near-plane intersection",
              "near-plane intersections") +
        " and " + count(o.intersections.camera_hit_fragments, "camera hit", "camera hits");
    if (has_occlusion(e)) {
      v += "; central occlusion up to " + percent(o.occlusion.central_max) + "% (mean " +
           percent(o.occlusion.central_mean) + "%), faded fragments counted by their opacity";
    }
    paragraphs.push_back(v + ".");
  }
  return paragraphs;
}

std::pair<std::string, std::string> report_viewer_pair(const std::vector<Evaluation>& runs) {
  if (runs.empty()) return {};
  const Evaluation* none = find_run(runs, "none");
  const std::string left = none ? none->summary.strategy : runs.front().summary.strategy;
  std::string right;
  if (const std::optional<std::size_t> best = best_for_thesis_goals(runs)) {
    right = runs[*best].summary.strategy;
  }
  if (right.empty() || right == left) {
    right.clear();
    for (const Evaluation& e : runs) {
      if (e.summary.strategy != left) {
        right = e.summary.strategy;
        break;
      }
    }
  }
  return {left, right};
}

std::string html_report(const Scene& scene, const std::vector<Evaluation>& runs,
                        const std::optional<SheetFigure>& sheet,
                        const std::string& viewer_section) {
  const std::string name = html_escape(scene.name);
  std::string h;
  h += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  h += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  // An empty icon, or the browser would look for favicon.ico beside the page.
  h += "<link rel=\"icon\" href=\"data:,\">\n";
  h += "<title>fragsim report: " + name + "</title>\n<style>\n";
  h += kStyle;
  h += "</style>\n</head>\n<body>\n<header>\n";
  h += "<h1>fragsim: strategies compared on scene " + name + "</h1>\n";
  const ResultsTable table = results_table(scene, runs);
  h += "<p class=\"meta\">" +
       html_escape(table.caption +
                   "; every strategy on the same scene and seed, deviation measured against "
                   "none.") +
       "</p>\n</header>\n";

  h += "<section class=\"reading\">\n<h2>Reading</h2>\n";
  for (const std::string& p : report_reading(runs)) h += "<p>" + html_escape(p) + "</p>\n";
  h += "</section>\n";

  h += "<section>\n<h2>Comparison</h2>\n" + results_html(table) + "<div class=\"notes\">\n";
  for (const std::string& n : table_notes(table)) h += "<p>" + n + "</p>\n";
  h += "</div>\n</section>\n";

  h += viewer_section;

  h += "<section>\n<h2>Over time</h2>\n<div class=\"charts\">\n";
  for (const ChartSpec& c : charts(scene, runs)) {
    h += "<figure>\n" + svg_line_chart(c.chart) + "<figcaption>" + html_escape(c.caption) +
         "</figcaption>\n</figure>\n";
  }
  h += "</div>\n";
  if (!runs.empty() && !has_occlusion(runs.front())) {
    h += "<p class=\"notes\">Occlusion was not measured (--no-occlusion): no occlusion "
         "charts.</p>\n";
  }
  h += "</section>\n";

  if (sheet) {
    h += "<section>\n<h2>Contact sheet</h2>\n<figure>\n<img class=\"sheet\" src=\"" +
         html_escape(sheet->file) + "\" width=\"" + std::to_string(sheet->width_px) +
         "\" height=\"" + std::to_string(sheet->height_px) + "\" alt=\"" +
         html_escape("contact sheet of scene " + scene.name) + "\">\n<figcaption>" +
         html_escape(sheet_caption(scene, *sheet)) + "</figcaption>\n</figure>\n</section>\n";
  }

  h += "<section>\n<h2>Scene settings</h2>\n<p class=\"notes\">The fully resolved scene, seed "
       "included: saved as a file, <code>fragsim compare --scene FILE</code> reruns it.</p>\n";
  h += "<pre class=\"ini\">" + ini_sections(scene_to_ini(scene)) + "</pre>\n</section>\n";
  h += "<footer>Written by <code>fragsim compare --report</code>.</footer>\n</body>\n</html>\n";
  return h;
}

std::vector<std::string> write_html_report(const std::string& dir, const Scene& scene,
                                           const std::vector<Evaluation>& runs,
                                           const FrameRecorder& recorder,
                                           const ViewerRecorder& viewer,
                                           const BundledThreeJs& three) {
  namespace fs = std::filesystem;
  std::vector<std::string> strategies;
  for (const Evaluation& e : runs) strategies.push_back(e.summary.strategy);
  SheetFigure figure;
  figure.file = kSheetFile;
  figure.steps = report_sheet_steps(scene);
  const Image sheet = contact_sheet(scene, recorder, strategies, figure.steps);
  figure.width_px = sheet.width();
  figure.height_px = sheet.height();
  const std::string sheet_path = (fs::path(dir) / kSheetFile).string();
  const std::string page_path = (fs::path(dir) / "index.html").string();
  const std::string table_path = (fs::path(dir) / kTableFile).string();
  std::string sheet_png;
  try {
    sheet_png = encode_png(sheet);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(sheet_path + ": " + e.what());
  }
  const auto [left, right] = report_viewer_pair(runs);
  OutputSet files;
  files.add(sheet_path, sheet_png);
  files.add(table_path, results_csv(results_table(scene, runs), false));
  files.add(page_path, html_report(scene, runs, figure,
                                   viewer_section_html(scene, viewer, left, right, three)));
  files.commit();
  return {page_path, sheet_path, table_path};
}

}  // namespace fragsim
