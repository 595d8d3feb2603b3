#include "report/results_table.hpp"

#include <algorithm>
#include <cstdio>

#include "io/number_format.hpp"
#include "report/html_escape.hpp"
#include "report/text_table.hpp"
#include "sim/camera_track_file.hpp"
#include "sim/explosion.hpp"
#include "sim/world.hpp"

namespace fragsim {
namespace {

using Cell = std::function<std::string(const Evaluation&)>;

// Irregular pieces differ in size by orders of magnitude, what such a scene tests, so the header
// says how much. Equal cubes say nothing more than their count.
std::string piece_sizes_text(const Scene& scene) {
  const bool mesh = !scene.object.mesh_file.empty();
  if (!mesh && scene.object.pattern == DebrisPattern::kGrid) return "";
  std::vector<double> v;
  for (const Piece& p : scene_pieces(scene)) v.push_back(piece_volume_m3(p));
  if (v.empty()) return "";
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  const double median = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
  char text[160];
  std::snprintf(text, sizeof text,
                " (%s; piece volume smallest %.3g m^3, median %.3g m^3, largest %.3g m^3)",
                mesh ? "from object.mesh_file" : "voronoi", v.front(), median, v.back());
  return text;
}

Cell text_cell(std::string RunSummary::*field) {
  return [field](const Evaluation& e) { return e.summary.*field; };
}

// A number held in one part of the summary (a member of a member of RunSummary).
template <class Part>
Cell count_cell(Part RunSummary::*part, int Part::*field) {
  return [part, field](const Evaluation& e) { return std::to_string(e.summary.*part.*field); };
}

template <class Part>
Cell fixed_cell(Part RunSummary::*part, double Part::*field, int decimals) {
  return [part, field, decimals](const Evaluation& e) {
    return fixed_text(e.summary.*part.*field, decimals);
  };
}

// Deviation is measured against the `none` run, so a run without it shows a dash, not a zero.
Cell deviation_cell(double DeviationStats::*field, int decimals, bool percent) {
  return [field, decimals, percent](const Evaluation& e) {
    if (!e.has_deviation) return std::string("-");
    const double v = e.summary.deviation.*field;
    return percent ? percent_text(v, decimals) : fixed_text(v, decimals);
  };
}

// --no-occlusion leaves the occlusion fields at zero. A dash says "not measured" where 0.0 would
// claim a clear screen.
Cell occlusion_cell(double OcclusionStats::*field) {
  return [field](const Evaluation& e) {
    return e.occlusion_per_step.empty() ? std::string("-")
                                        : percent_text(e.summary.occlusion.*field, 1);
  };
}

std::string exits_text(const RunSummary& s) {
  return std::to_string(s.exits.top) + "/" + std::to_string(s.exits.bottom) + "/" +
         std::to_string(s.exits.left) + "/" + std::to_string(s.exits.right) + "/" +
         std::to_string(s.exits.near) + "/" + std::to_string(s.exits.stayed);
}

std::string pushed_exits_text(const RunSummary& s) {
  if (s.activity.forced_fragments == 0) return "-";
  return std::to_string(s.pushed_exits.top) + "/" + std::to_string(s.pushed_exits.bottom) + "/" +
         std::to_string(s.pushed_exits.left) + "/" + std::to_string(s.pushed_exits.right) + "/" +
         std::to_string(s.pushed_exits.near) + "/" + std::to_string(s.pushed_exits.stayed);
}

std::vector<ResultsNote> run_notes(const Scene& scene, const std::vector<Evaluation>& runs) {
  std::vector<ResultsNote> notes;
  for (const Evaluation& e : runs) {
    const RunSummary& s = e.summary;
    // min_near_m is 0 when nothing was recorded; below the camera's near distance the run moved
    // the near plane, and what that costs is the depth resolution.
    if (s.activity.min_near_m > 0.0 && s.activity.min_near_m < scene.camera.near_m) {
      const double ref_m = scene.strategies.near_plane.ref_distance_m;
      notes.push_back({s.strategy + ": near distance down to " +
                       fixed_text(s.activity.min_near_m, 3) + " m, depth step at " +
                       fixed_text(ref_m, 1) +
                       " m: " + fixed_text(1e3 * s.activity.depth_step_m, 3) + " mm" +
                       (z_fighting(s, ref_m) ? " (z-fighting)" : "")});
    }
    if (s.activity.wall_contacts > 0) {
      notes.push_back({s.strategy + ": " + std::to_string(s.activity.wall_contacts) +
                       " contact points with the wall"});
    }
  }
  std::string cost = "cost per step, median / p95:";
  for (const Evaluation& e : runs) {
    const RunSummary& s = e.summary;
    cost += (&e == &runs.front() ? " " : "; ") + s.strategy + " " +
            fixed_text(s.cost.physics_ms_median, 2) + "/" + fixed_text(s.cost.physics_ms_p95, 2) +
            " + " + fixed_text(s.cost.strategy_ms_median, 2) + "/" +
            fixed_text(s.cost.strategy_ms_p95, 2) + " ms";
  }
  notes.push_back({cost + " (physics + strategy)", true});
  for (const Evaluation& e : runs) {
    if (e.summary.activity.unsaved_by_cap > 0) {
      notes.push_back({e.summary.strategy + ": " +
                       std::to_string(e.summary.activity.unsaved_by_cap) +
                       " fragments the acceleration cap left unsaved (capped and still "
                       "intersecting)"});
    }
  }
  return notes;
}

std::string verdict(const std::vector<Evaluation>& runs, std::optional<std::size_t> best) {
  if (!best) return "";
  const RunSummary& s = runs[*best].summary;
  const int n = thesis_goal_failures(s);
  return "best for the thesis's goals (no intersections or vanished fragments, then least "
         "deviation, then most near misses): " +
         s.strategy + " (" +
         (n == 0 ? "no intersections"
                 : std::to_string(n) + (s.intersections.vanished_fragments > 0
                                            ? " intersections or vanished"
                                            : " intersections")) +
         (runs[*best].has_deviation ? ", mean deviation " + fixed_text(s.deviation.mean_m, 4) + " m"
                                    : std::string()) +
         ", " + std::to_string(s.intersections.near_misses) + " near misses)";
}

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

// Escaped for HTML, `name` as <code>name</code>.
std::string html_with_code(const std::string& text) {
  std::string out;
  bool in_code = false;
  std::size_t start = 0;
  for (std::size_t at = text.find('`'); at != std::string::npos; at = text.find('`', start)) {
    out += html_escape(text.substr(start, at - start));
    out += in_code ? "</code>" : "<code>";
    in_code = !in_code;
    start = at + 1;
  }
  out += html_escape(text.substr(start));
  if (in_code) out += "</code>";
  return out;
}

}  // namespace

std::string column_title(const ResultsColumn& column) {
  std::string title = column.header;
  if (!column.unit.empty()) {
    title += '_';
    for (const char c : column.unit) {
      if (c != ' ') title += c;
    }
  }
  if (!column.parts.empty()) title += " " + column.parts;
  return title;
}

std::vector<ResultsColumn> results_columns(double near_miss_m) {
  using B = LegendBreak;
  const std::string miss = "near misses within " + fixed_text(near_miss_m, 2) + " m";
  return {
      {.header = "strategy",
       .explanation = "the strategy compared",
       .cell = text_cell(&RunSummary::strategy)},
      {.header = "near",
       .explanation = "fragments meeting the near rectangle (swept between steps)",
       .legend_key = "near",
       .legend = "fragments meeting the near rectangle (swept)",
       .legend_break = B::comma,
       .cell = count_cell(&RunSummary::intersections, &IntersectionCounts::near_fragments)},
      {.header = "near_st",
       .explanation = "fragment-steps meeting the near rectangle",
       .legend_key = "near_st",
       .legend = "fragment-steps",
       .legend_break = B::comma,
       .cell = count_cell(&RunSummary::intersections, &IntersectionCounts::near_fragment_steps)},
      {.header = "cam",
       .explanation = "fragments touching the camera body",
       .legend_key = "cam",
       .legend = "camera-body hits",
       .legend_break = B::comma,
       .cell = count_cell(&RunSummary::intersections, &IntersectionCounts::camera_hit_fragments)},
      {.header = "vanished",
       .explanation = "fragments that faded below half opacity in view or met the near plane "
                      "invisible (fade); a failure of the thesis's goals, as a cut is",
       .legend_key = "vanished",
       .legend = "fragments faded out in view (`fade`)",
       .legend_break = B::line,
       .cell = count_cell(&RunSummary::intersections, &IntersectionCounts::vanished_fragments)},
      {.header = "dev_mean",
       .unit = "m",
       .explanation = "mean over fragments of the largest distance from the none run",
       .legend_key = "dev",
       .legend = "deviation from the `none` run",
       .cell = deviation_cell(&DeviationStats::mean_m, 4, false)},
      {.header = "dev_max",
       .unit = "m",
       .explanation = "largest deviation of any fragment",
       .cell = deviation_cell(&DeviationStats::max_m, 3, false)},
      {.header = "dev>1cm",
       .unit = "%",
       .explanation = "share of fragments moved more than 1 cm",
       .cell = deviation_cell(&DeviationStats::deviated_share, 1, true)},
      {.header = "occ_mean",
       .unit = "%",
       .explanation = "mean share of the screen covered",
       .legend_key = "occ/ctr",
       .legend = "screen and central share covered",
       .cell = occlusion_cell(&OcclusionStats::mean)},
      {.header = "occ_max",
       .unit = "%",
       .explanation = "largest share of the screen covered",
       .cell = occlusion_cell(&OcclusionStats::max)},
      {.header = "ctr_max",
       .unit = "%",
       .explanation = "largest share of the central region covered",
       .cell = occlusion_cell(&OcclusionStats::central_max)},
      {.header = "exits",
       .parts = "T/B/L/R/N/S",
       .explanation = "how fragments left the screen: top/bottom/left/right/near/stayed",
       .legend_key = "exits",
       .legend = "Top/Bottom/Left/Right/Near/Stayed",
       .legend_break = B::line,
       .cell = [](const Evaluation& e) { return exits_text(e.summary); }},
      {.header = "pushed_exits",
       .parts = "T/B/L/R/N/S",
       .explanation =
           "how the fragments the strategy pushed left the screen (top/bottom/left/right/"
           "near/stayed): the edges edge-min.edge_weights asks for",
       .terminal = false,
       .cell = [](const Evaluation& e) { return pushed_exits_text(e.summary); }},
      {.header = "miss",
       .explanation = "near misses: passed close to the eye without touching",
       .legend_key = "miss",
       .legend = miss,
       .cell = count_cell(&RunSummary::intersections, &IntersectionCounts::near_misses)},
      {.header = "cand0",
       .explanation = "edge candidates at t = 0",
       .legend_key = "cand0",
       .legend = "edge candidates at t = 0",
       .cell = count_cell(&RunSummary::activity, &ActivityTotals::candidates_initial)},
      {.header = "impulse",
       .unit = "N s",
       .explanation = "total impulse applied",
       .cell = fixed_cell(&RunSummary::activity, &ActivityTotals::impulse_Ns, 2)},
      {.header = "capped",
       .explanation = "force-steps cut by the acceleration cap",
       .legend_key = "capped",
       .legend = "forces cut by a_max",
       .cell = count_cell(&RunSummary::activity, &ActivityTotals::capped_forces)},
      {.header = "near_min",
       .unit = "m",
       .explanation = "smallest near distance used",
       .cell = fixed_cell(&RunSummary::activity, &ActivityTotals::min_near_m, 3)},
      {.header = "phys",
       .unit = "ms",
       .explanation = "median wall-clock time of a physics step",
       .legend_key = "phys/strat",
       .legend = "median per step",
       .timing = true,
       .cell = fixed_cell(&RunSummary::cost, &RunCost::physics_ms_median, 3)},
      {.header = "strat",
       .unit = "ms",
       .explanation = "median wall-clock time of the strategy in a step",
       .timing = true,
       .cell = fixed_cell(&RunSummary::cost, &RunCost::strategy_ms_median, 3)},
  };
}

ResultsTable results_table(const Scene& scene, const std::vector<Evaluation>& runs) {
  ResultsTable t;
  t.scene_name = scene.name;
  t.caption = std::to_string(scene.fragment_count()) + " fragments" + piece_sizes_text(scene) +
              ", " + std::to_string(scene.step_count()) + " steps of " +
              fixed_text(scene.sim.dt_s, 5) + " s, seed " + std::to_string(scene.sim.seed) +
              ", ODE " + World::ode_version();
  if (auto coverage = track_coverage_warning(scene)) t.warnings.push_back(*coverage);
  t.columns = results_columns(scene.metrics.near_miss_m);
  for (const Evaluation& e : runs) {
    std::vector<std::string> row;
    for (const ResultsColumn& c : t.columns) row.push_back(c.cell(e));
    t.rows.push_back(std::move(row));
  }
  const std::optional<std::size_t> best = best_for_thesis_goals(runs);
  if (best && thesis_goal_failures(runs[*best].summary) == 0) t.best_row = best;
  t.notes = run_notes(scene, runs);
  t.verdict = verdict(runs, best);
  return t;
}

std::string legend_text(const ResultsTable& table, bool timings, bool line_breaks) {
  std::string out;
  const char* pending = "";
  for (const ResultsColumn& c : table.columns) {
    if (c.legend.empty() || (c.timing && !timings)) continue;
    out += pending + c.legend_key + ": " + c.legend;
    switch (c.legend_break) {
      case LegendBreak::comma:
        pending = ", ";
        break;
      case LegendBreak::semicolon:
        pending = "; ";
        break;
      case LegendBreak::line:
        pending = line_breaks ? ";\n" : "; ";
        break;
    }
  }
  return out.empty() ? out : out + ".";
}

std::string results_text(const ResultsTable& table) {
  std::vector<std::string> headers;
  for (const ResultsColumn& c : table.columns) {
    if (c.terminal) headers.push_back(column_title(c));
  }
  std::vector<std::vector<std::string>> rows;
  for (const auto& row : table.rows) {
    rows.emplace_back();
    for (std::size_t k = 0; k < table.columns.size(); ++k) {
      if (table.columns[k].terminal) rows.back().push_back(row[k]);
    }
  }
  std::string out = "scene " + table.scene_name + ": " + table.caption + "\n";
  for (const std::string& w : table.warnings) out += "warning: " + w + "\n";
  out += "\n" + aligned_text_table(headers, rows) + "\n" + legend_text(table, true, true) + "\n";
  for (const ResultsNote& n : table.notes) out += n.text + "\n";
  if (!table.verdict.empty()) out += table.verdict + "\n";
  return out;
}

// Each header's unit on a second line (dev_mean over m) keeps the 16 columns within a
// 1200-pixel window.
std::string results_html(const ResultsTable& table) {
  std::string out = "<div class=\"table-wrap\"><table>\n<thead><tr>";
  for (const ResultsColumn& c : table.columns) {
    if (c.timing) continue;
    const std::string& second = c.unit.empty() ? c.parts : c.unit;
    out += "<th title=\"" + html_escape(c.explanation) + "\">" + html_escape(c.header) + "<span>" +
           (second.empty() ? "&nbsp;" : html_escape(second)) + "</span></th>";
  }
  out += "</tr></thead>\n<tbody>\n";
  for (std::size_t i = 0; i < table.rows.size(); ++i) {
    out += table.best_row == i ? "<tr class=\"best\">" : "<tr>";
    for (std::size_t k = 0; k < table.columns.size(); ++k) {
      if (table.columns[k].timing) continue;
      out += "<td>" + html_escape(table.rows[i][k]) + "</td>";
    }
    out += "</tr>\n";
  }
  return out + "</tbody></table></div>\n";
}

std::string legend_html(const ResultsTable& table) {
  return html_with_code(legend_text(table, false, false));
}

std::string results_csv(const ResultsTable& table, bool timings) {
  std::string out;
  const auto line = [&](const std::vector<std::string>& cells) {
    bool first = true;
    for (std::size_t k = 0; k < table.columns.size(); ++k) {
      if (table.columns[k].timing && !timings) continue;
      if (!first) out += ',';
      out += csv_field(cells[k]);
      first = false;
    }
    out += '\n';
  };
  std::vector<std::string> titles;
  for (const ResultsColumn& c : table.columns) titles.push_back(column_title(c));
  line(titles);
  for (const auto& row : table.rows) line(row);
  return out;
}

}  // namespace fragsim
