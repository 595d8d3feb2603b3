// The HTML report (fragsim compare --report DIR): the reading in prose on hand-made summaries,
// the page built from a real comparison of thesis125.ini, and the command end to end: the same
// bytes on a rerun (page, sheet and table.csv), a non-empty folder refused without --force, an
// unwritable folder a one-line error. The chart and the escaping have their own tests
// (svg_chart_test.cpp, html_escape_test.cpp).

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "experiments/evaluation.hpp"
#include "render/image.hpp"
#include "report/html_escape.hpp"
#include "report/html_report.hpp"
#include "sim/scene_file.hpp"
#include "support/run_fragsim.hpp"
#include "support/text_count.hpp"

namespace fragsim {
namespace {

namespace fs = std::filesystem;
using test::occurrences;

const std::string kThesis125 = std::string(FRAGSIM_DATA_DIR) + "/scenes/thesis125.ini";

std::string read_all(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::path(::testing::TempDir()) / name;
  fs::remove_all(d);
  return d;
}

// --- the reading, on hand-made summaries ---

Evaluation made_run(const std::string& strategy, int near, int cam, double dev_mean_m,
                    double central_max = 0.5) {
  Evaluation e;
  e.has_deviation = true;
  RunSummary& s = e.summary;
  s.strategy = strategy;
  s.intersections.near_fragments = near;
  s.intersections.near_fragment_steps = 2 * near;
  s.intersections.camera_hit_fragments = cam;
  s.deviation.mean_m = dev_mean_m;
  s.deviation.max_m = 10 * dev_mean_m;
  s.occlusion.mean = 0.1;
  s.occlusion.max = 0.9;
  s.occlusion.central_mean = 0.2;
  s.occlusion.central_max = central_max;
  e.near_per_step = {0, near, 0};
  e.candidates_per_step = {0, 0, 0};
  e.occlusion_per_step = {0.1, 0.9, 0.1};
  e.central_occlusion_per_step = {0.2, central_max, 0.2};
  e.camera.resize(4);
  return e;
}

std::string all_text(const std::vector<std::string>& paragraphs) {
  std::string out;
  for (const std::string& p : paragraphs) out += p + "\n";
  return out;
}

TEST(HtmlReport, ReadingNamesTheBestAndItsCostAgainstNone) {
  const std::vector<Evaluation> runs{
      made_run("none", 18, 34, 0.0, 0.963), made_run("deflect-all", 0, 0, 22.17),
      made_run("edge", 0, 3, 12.0), made_run("edge-min", 0, 0, 0.072, 0.939)};
  const std::string text = all_text(report_reading(runs));
  EXPECT_NE(text.find("Without control (none), 18 fragments met the near plane (36 "
                      "fragment-steps) and 34 hit the camera body."),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("edge-min met the thesis's goals"), std::string::npos) << text;
  EXPECT_NE(text.find("0 near-plane intersections, 0 camera hits, mean deviation 0.072 m"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("up to 93.9% (mean 20.0%) against 96.3% (mean 20.0%) without control"),
            std::string::npos)
      << text;
  // deflect-all also kept the camera clear, edge did not (3 camera hits).
  EXPECT_NE(text.find("with more deviation: deflect-all (mean deviation 22.170 m)."),
            std::string::npos)
      << text;
  EXPECT_EQ(text.find("edge (mean"), std::string::npos);
}

TEST(HtmlReport, ReadingSaysWhenNoStrategyMetTheGoals) {
  const std::vector<Evaluation> runs{made_run("none", 18, 34, 0.0), made_run("wall", 6, 11, 2.35),
                                     made_run("edge", 1, 3, 12.0)};
  const std::string text = all_text(report_reading(runs));
  EXPECT_NE(text.find("No strategy met the thesis's goals"), std::string::npos) << text;
  EXPECT_NE(text.find("The closest, edge: 1 near-plane intersection, 3 camera hits"),
            std::string::npos)
      << text;
  EXPECT_EQ(text.find("met the thesis's goals best"), std::string::npos);

  const std::string only_none = all_text(report_reading({made_run("none", 1, 0, 0.0)}));
  EXPECT_NE(only_none.find("Only none ran"), std::string::npos) << only_none;
}

// fade keeps the near plane clear but makes debris vanish: a failure of the goals, named with
// its count, while edge-min, with more deviation, is the best.
TEST(HtmlReport, ReadingCountsVanishedFragmentsAsAFailure) {
  Evaluation fade = made_run("fade", 0, 2, 0.0, 0.8);
  fade.summary.intersections.vanished_fragments = 40;
  const std::vector<Evaluation> runs{made_run("none", 18, 34, 0.0, 0.963), fade,
                                     made_run("edge-min", 0, 0, 0.072, 0.939)};
  const std::string text = all_text(report_reading(runs));
  EXPECT_NE(text.find("edge-min met the thesis's goals best"), std::string::npos) << text;
  EXPECT_NE(text.find("fade made 40 fragments vanish in view"), std::string::npos) << text;
  EXPECT_NE(text.find("It left 0 near-plane intersections and 2 camera hits; central occlusion "
                      "up to 80.0% (mean 20.0%)"),
            std::string::npos)
      << text;
  // Alone against none, fade has not met the goals: it is the closest, with its vanished count.
  Evaluation clean_fade = made_run("fade", 0, 0, 0.0, 0.8);
  clean_fade.summary.intersections.vanished_fragments = 40;
  const std::string alone = all_text(report_reading({made_run("none", 18, 34, 0.0), clean_fade}));
  EXPECT_NE(alone.find("No strategy met the thesis's goals"), std::string::npos) << alone;
  EXPECT_NE(alone.find("The closest, fade: 0 near-plane intersections, 0 camera hits, 40 "
                       "fragments vanished"),
            std::string::npos)
      << alone;
}

TEST(HtmlReport, EscapesSceneAndStrategyNames) {
  Scene scene;
  scene.name = "<b>bold</b> & \"quoted\"";
  std::vector<Evaluation> runs{made_run("none", 1, 0, 0.0), made_run("x<y>", 0, 0, 0.5)};
  const std::string page = html_report(scene, runs, std::nullopt);
  EXPECT_EQ(page.find("<b>bold</b>"), std::string::npos);
  EXPECT_NE(page.find("&lt;b&gt;bold&lt;/b&gt; &amp; &quot;quoted&quot;"), std::string::npos);
  EXPECT_EQ(page.find("x<y>"), std::string::npos);
  EXPECT_NE(page.find("<td>x&lt;y&gt;</td>"), std::string::npos);
  EXPECT_NE(page.find("x&lt;y&gt; met the thesis&#39;s goals"), std::string::npos);
}

// --- the page from a real comparison ---

// thesis125.ini compared once for the tests below (0.2 s), with the report's frames recorded.
struct Compared {
  Scene scene = load_scene(kThesis125);
  std::vector<std::string> names{"none", "wall", "near-plane", "edge", "edge-min"};
  FrameRecorder recorder{report_sheet_steps(scene)};
  std::vector<Evaluation> runs = compare(scene, names, true, &recorder);
};

const Compared& compared() {
  static const Compared c;
  return c;
}

TEST(HtmlReport, PageHasTheTableRowChartsAndSettingsOfTheComparison) {
  const Compared& c = compared();
  SheetFigure sheet{"sheet.png", 100, 50, report_sheet_steps(c.scene)};
  const std::string page = html_report(c.scene, c.runs, sheet);
  const std::optional<std::size_t> best = best_for_thesis_goals(c.runs);
  ASSERT_TRUE(best);
  for (std::size_t i = 0; i < c.runs.size(); ++i) {
    const RunSummary& s = c.runs[i].summary;
    const bool met = s.intersections.near_fragments + s.intersections.camera_hit_fragments == 0;
    const std::string row = std::string(i == *best && met ? "<tr class=\"best\">" : "<tr>") +
                            "<td>" + s.strategy + "</td><td>" +
                            std::to_string(s.intersections.near_fragments) + "</td><td>" +
                            std::to_string(s.intersections.near_fragment_steps) + "</td><td>" +
                            std::to_string(s.intersections.camera_hit_fragments) + "</td>";
    EXPECT_EQ(occurrences(page, row), 1u) << row;
  }
  EXPECT_EQ(occurrences(page, "<tr"), c.runs.size() + 1);  // the header and a row per strategy
  // The reading names the best strategy (edge-min clears thesis125, see docs/guide.md).
  EXPECT_EQ(c.runs[*best].summary.strategy, "edge-min");
  EXPECT_NE(page.find("<p>edge-min met the thesis&#39;s goals best"), std::string::npos);
  // Five charts, a line per strategy each, and the sheet beside the page.
  EXPECT_EQ(occurrences(page, "<svg"), 5u);
  EXPECT_EQ(occurrences(page, "<path stroke="), 5 * c.runs.size());
  EXPECT_NE(page.find("<img class=\"sheet\" src=\"sheet.png\" width=\"100\" height=\"50\""),
            std::string::npos);
  // The settings: every line of the resolved scene file.
  std::istringstream ini(scene_to_ini(c.scene));
  for (std::string line; std::getline(ini, line);) {
    EXPECT_NE(page.find(html_escape(line)), std::string::npos) << line;
  }
}

TEST(HtmlReport, PageFetchesNothingAndRunsNoScript) {
  const Compared& c = compared();
  std::string page = html_report(c.scene, c.runs, std::nullopt);
  EXPECT_EQ(page.find("<script"), std::string::npos);
  EXPECT_EQ(page.find("@import"), std::string::npos);
  EXPECT_EQ(page.find("url("), std::string::npos);
  // The only URL is SVG's namespace name, an identifier that is never fetched.
  const std::string ns = "xmlns=\"http://www.w3.org/2000/svg\"";
  for (std::size_t at = page.find(ns); at != std::string::npos; at = page.find(ns)) {
    page.erase(at, ns.size());
  }
  EXPECT_EQ(page.find("://"), std::string::npos);
}

TEST(HtmlReport, WithoutOcclusionThePageSaysSoAndDrawsNoOcclusionChart) {
  std::vector<Evaluation> runs{made_run("none", 1, 0, 0.0), made_run("edge-min", 0, 0, 0.1)};
  for (Evaluation& e : runs) {
    e.occlusion_per_step.clear();
    e.central_occlusion_per_step.clear();
  }
  const std::string page = html_report(Scene{}, runs, std::nullopt);
  EXPECT_EQ(occurrences(page, "<svg"), 3u);
  EXPECT_NE(page.find("Occlusion was not measured"), std::string::npos);
}

// --- the command ---

TEST(HtmlReport, SameSceneAndSeedWriteTheSameBytes) {
  const fs::path a = fresh_dir("fragsim_report_a");
  const fs::path b = fresh_dir("fragsim_report_b");
  for (const fs::path& d : {a, b}) {
    const test::Result r =
        test::run_fragsim("compare --scene " + kThesis125 + " --report " + d.string());
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_NE(r.out.find("wrote " + (d / "index.html").string()), std::string::npos) << r.out;
  }
  const std::string page = read_all(a / "index.html");
  ASSERT_GT(page.size(), 10000u);
  EXPECT_EQ(page, read_all(b / "index.html"));
  EXPECT_EQ(read_all(a / "sheet.png"), read_all(b / "sheet.png"));
  // The page's table as CSV beside it, linked from the page, as repeatable as the page.
  const std::string table = read_all(a / "table.csv");
  EXPECT_EQ(table, read_all(b / "table.csv"));
  EXPECT_EQ(table.rfind("strategy,near,near_st,cam,vanished,dev_mean_m,", 0), 0u) << table;
  EXPECT_EQ(table.find("_ms"), std::string::npos) << table;
  EXPECT_NE(page.find("<a href=\"table.csv\">"), std::string::npos);
  // The page's image is the sheet beside it, at its size.
  const Image sheet = read_png((a / "sheet.png").string());
  EXPECT_NE(page.find("src=\"sheet.png\" width=\"" + std::to_string(sheet.width()) +
                      "\" height=\"" + std::to_string(sheet.height()) + "\""),
            std::string::npos);
}

TEST(HtmlReport, NonEmptyFolderIsRefusedWithoutForce) {
  const fs::path d = fresh_dir("fragsim_report_full");
  fs::create_directories(d);
  std::ofstream(d / "keep.txt") << "mine\n";
  const std::string run = "compare --strategies none,edge-min --scene " + kThesis125 +
                          " --simulation.duration_s 0.2 --report " + d.string();
  const test::Result refused = test::run_fragsim(run);
  EXPECT_EQ(refused.status, 2) << refused.out;
  EXPECT_NE(refused.out.find("--report"), std::string::npos) << refused.out;
  EXPECT_NE(refused.out.find("--force"), std::string::npos) << refused.out;
  EXPECT_FALSE(fs::exists(d / "index.html"));
  EXPECT_EQ(read_all(d / "keep.txt"), "mine\n");
  const test::Result forced = test::run_fragsim(run + " --force");
  EXPECT_EQ(forced.status, 0) << forced.out;
  EXPECT_TRUE(fs::exists(d / "index.html"));
  EXPECT_TRUE(fs::exists(d / "sheet.png"));
}

TEST(HtmlReport, UnwritableFolderIsAOneLineError) {
  const test::Result r = test::run_fragsim("compare --strategies none --scene " + kThesis125 +
                                           " --report /proc/fragsim/cannot");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
  EXPECT_EQ(r.out.rfind("fragsim compare: --report: /proc/fragsim/cannot", 0), 0u) << r.out;
}

}  // namespace
}  // namespace fragsim
