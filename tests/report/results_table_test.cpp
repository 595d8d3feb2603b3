// The results table model: its columns in order, the terminal, HTML and CSV renderings of a
// summary built by hand giving the same cell texts, and notes that come from the runs' numbers
// rather than from strategy names.

#include <gtest/gtest.h>

#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "report/results_table.hpp"

namespace fragsim {
namespace {

Evaluation hand_run(const std::string& strategy) {
  Evaluation e;
  e.has_deviation = true;
  RunSummary& s = e.summary;
  s.strategy = strategy;
  s.intersections.near_fragments = 3;
  s.intersections.near_fragment_steps = 7;
  s.intersections.camera_hit_fragments = 2;
  s.deviation.mean_m = 0.08205;         // stored just below the half: 0.0820
  s.deviation.max_m = 8.7285;           // stored just above the half: 8.729
  s.deviation.deviated_share = 0.0375;  // 3.75 exactly, a tie: to even, 3.8
  s.occlusion.mean = 0.079;
  s.occlusion.max = -1e-12;  // a rounding residue: "0.0", never "-0.0"
  s.occlusion.central_max = 0.9634;
  s.exits.top = 749;
  s.exits.bottom = 489;
  s.exits.left = 240;
  s.exits.right = 233;
  s.exits.near = 17;
  s.exits.stayed = 0;
  // 65 pushed; of them, 29 left by the top, 11 the bottom, 12 left, 13 right.
  s.activity.forced_fragments = 65;
  s.pushed_exits.top = 29;
  s.pushed_exits.bottom = 11;
  s.pushed_exits.left = 12;
  s.pushed_exits.right = 13;
  s.intersections.near_misses = 616;
  s.activity.candidates_initial = 51;
  s.activity.impulse_Ns = 28.635;
  s.activity.capped_forces = 4;
  s.activity.min_near_m = 0.1;
  s.cost.physics_ms_median = 0.9375;
  s.cost.strategy_ms_median = 0.0345;
  e.occlusion_per_step = {0.079};
  return e;
}

Scene hand_scene() {
  Scene scene;
  scene.name = "hand";
  scene.metrics.near_miss_m = 1.0;
  return scene;
}

std::vector<std::string> words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

std::vector<std::string> lines(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> out;
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

// The <td> texts of the page's row `row` (0 = the first run).
std::vector<std::string> html_cells(const std::string& html, std::size_t row) {
  std::size_t at = html.find("<tbody>");
  for (std::size_t r = 0; r <= row; ++r) at = html.find("<tr", at + 1);
  const std::size_t end = html.find("</tr>", at);
  std::vector<std::string> out;
  for (std::size_t td = html.find("<td>", at); td < end; td = html.find("<td>", td + 1)) {
    const std::size_t close = html.find("</td>", td);
    out.push_back(html.substr(td + 4, close - td - 4));
  }
  return out;
}

std::vector<std::string> csv_cells(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  for (std::string c; std::getline(in, c, ',');) out.push_back(c);
  return out;
}

TEST(ResultsTable, ColumnsInOrder) {
  std::vector<std::string> titles;
  for (const ResultsColumn& c : results_columns(1.0)) titles.push_back(column_title(c));
  const std::vector<std::string> want{"strategy",
                                      "near",
                                      "near_st",
                                      "cam",
                                      "vanished",
                                      "dev_mean_m",
                                      "dev_max_m",
                                      "dev>1cm_%",
                                      "occ_mean_%",
                                      "occ_max_%",
                                      "ctr_max_%",
                                      "exits T/B/L/R/N/S",
                                      "pushed_exits T/B/L/R/N/S",
                                      "miss",
                                      "cand0",
                                      "impulse_Ns",
                                      "capped",
                                      "near_min_m",
                                      "phys_ms",
                                      "strat_ms"};
  EXPECT_EQ(titles, want);
  for (const ResultsColumn& c : results_columns(1.0)) {
    EXPECT_FALSE(c.explanation.empty()) << c.header;
    EXPECT_TRUE(c.cell) << c.header;
    EXPECT_EQ(c.timing, c.unit == "ms") << c.header;
  }
}

TEST(ResultsTable, TerminalPageAndCsvShowTheSameCells) {
  Evaluation none = hand_run("none");
  none.has_deviation = false;
  none.summary.activity.forced_fragments = 0;  // pushed nothing: no pushed exits to show
  Evaluation other = hand_run("other");
  other.occlusion_per_step.clear();  // --no-occlusion
  Evaluation odd = hand_run("odd");
  odd.summary.deviation.mean_m = std::numeric_limits<double>::quiet_NaN();
  odd.summary.activity.impulse_Ns = std::numeric_limits<double>::infinity();
  const std::vector<Evaluation> runs{hand_run("edge-min"), none, other, odd};
  const ResultsTable table = results_table(hand_scene(), runs);
  ASSERT_EQ(table.rows.size(), runs.size());

  const std::vector<std::string> want_first{
      "edge-min",        "3",    "7",   "2",     "0",    "0.0820",
      "8.729",           "3.8",  "7.9", "0.0",   "96.3", "749/489/240/233/17/0",
      "29/11/12/13/0/0", "616",  "51",  "28.64", "4",    "0.100",
      "0.938",           "0.035"};
  EXPECT_EQ(table.rows[0], want_first);
  EXPECT_EQ(table.rows[1][5], "-");  // no deviation reference
  EXPECT_EQ(table.rows[1][7], "-");
  EXPECT_EQ(table.rows[1][12], "-");
  EXPECT_EQ(table.rows[2][8], "-");  // occlusion not measured
  EXPECT_EQ(table.rows[2][10], "-");
  EXPECT_EQ(table.rows[3][5], "nan");
  EXPECT_EQ(table.rows[3][15], "inf");

  const std::vector<std::string> text = lines(results_text(table));
  const std::string html = results_html(table);
  const std::vector<std::string> csv = lines(results_csv(table, true));
  const std::vector<std::string> page_csv = lines(results_csv(table, false));
  ASSERT_GE(text.size(), 4 + runs.size());
  EXPECT_EQ(text[0], "scene hand: " + table.caption);
  for (std::size_t i = 0; i < runs.size(); ++i) {
    // The terminal drops pushed_exits (column 12), a detail for the page and table.csv.
    std::vector<std::string> on_terminal = table.rows[i];
    on_terminal.erase(on_terminal.begin() + 12);
    EXPECT_EQ(words(text[4 + i]), on_terminal);
    EXPECT_EQ(csv_cells(csv[1 + i]), table.rows[i]);
    // The page and its CSV drop the two timing columns, the last two.
    const std::vector<std::string> untimed(table.rows[i].begin(), table.rows[i].end() - 2);
    EXPECT_EQ(html_cells(html, i), untimed);
    EXPECT_EQ(csv_cells(page_csv[1 + i]), untimed);
  }
  std::vector<std::string> titles;
  for (const ResultsColumn& c : table.columns) titles.push_back(column_title(c));
  EXPECT_EQ(csv_cells(csv[0]), titles);
  std::size_t at = 0;
  for (const std::string& title : titles) {
    if (title.rfind("pushed_exits", 0) == 0) continue;
    at = text[2].find(title, at);
    EXPECT_NE(at, std::string::npos) << title;
  }
}

TEST(ResultsTable, TerminalLegendIsTheReadmeText) {
  const ResultsTable table = results_table(hand_scene(), {hand_run("none")});
  EXPECT_EQ(legend_text(table, true, true),
            "near: fragments meeting the near rectangle (swept), near_st: fragment-steps, cam: "
            "camera-body hits, vanished: fragments faded out in view (`fade`);\ndev: deviation "
            "from the `none` run; occ/ctr: screen and central "
            "share covered; exits: Top/Bottom/Left/Right/Near/Stayed;\nmiss: near misses within "
            "1.00 m; cand0: edge candidates at t = 0; capped: forces cut by a_max; phys/strat: "
            "median per step.");
  // The page has no timings, so its legend ends at capped; code spans for names.
  const std::string page = legend_html(table);
  EXPECT_EQ(page.find('\n'), std::string::npos);
  EXPECT_NE(page.find("from the <code>none</code> run"), std::string::npos) << page;
  const std::string end = "; capped: forces cut by a_max.";
  EXPECT_EQ(page.substr(page.size() - end.size()), end) << page;
}

TEST(ResultsTable, NotesComeFromTheRunsNumbersNotTheirNames) {
  const Scene scene = hand_scene();
  Evaluation pulled = hand_run("pull-in");  // a strategy the table has never heard of
  pulled.summary.activity.min_near_m = 0.01;
  pulled.summary.activity.depth_step_m = 0.000596;
  Evaluation walled = hand_run("box");
  walled.summary.activity.wall_contacts = 12;
  Evaluation untouched = hand_run("near-plane");  // the name alone earns no note
  Evaluation capped = hand_run("edge");
  capped.summary.activity.unsaved_by_cap = 5;
  const ResultsTable table = results_table(scene, {pulled, walled, untouched, capped});
  std::vector<std::string> untimed;
  int timed = 0;
  for (const ResultsNote& n : table.notes) {
    if (n.timing) {
      ++timed;
      EXPECT_EQ(n.text.rfind("cost per step, median / p95: pull-in 0.94/0.00 + 0.03/0.00 ms; "
                             "box ",
                             0),
                0u)
          << n.text;
    } else {
      untimed.push_back(n.text);
    }
  }
  EXPECT_EQ(timed, 1);
  const std::vector<std::string> want{
      "pull-in: near distance down to 0.010 m, depth step at 10.0 m: 0.596 mm",
      "box: 12 contact points with the wall",
      "edge: 5 fragments the acceleration cap left unsaved (capped and still intersecting)"};
  EXPECT_EQ(untimed, want);
  EXPECT_EQ(scene.strategies.near_plane.ref_distance_m, 10.0);
}

TEST(ResultsTable, BestRowOnlyWhenTheGoalsWereMet) {
  Evaluation none = hand_run("none");
  Evaluation clean = hand_run("clean");
  clean.summary.intersections.near_fragments = 0;
  clean.summary.intersections.camera_hit_fragments = 0;
  const ResultsTable met = results_table(hand_scene(), {none, clean});
  ASSERT_TRUE(met.best_row);
  EXPECT_EQ(*met.best_row, 1u);
  EXPECT_NE(results_html(met).find("<tr class=\"best\"><td>clean</td>"), std::string::npos);
  EXPECT_EQ(met.verdict,
            "best for the thesis's goals (no intersections or vanished fragments, then least "
            "deviation, then most near misses): clean (no intersections, mean deviation 0.0820 m, "
            "616 near misses)");

  const ResultsTable missed = results_table(hand_scene(), {none, hand_run("leaky")});
  EXPECT_FALSE(missed.best_row);
  EXPECT_EQ(results_html(missed).find("class=\"best\""), std::string::npos);
  EXPECT_NE(missed.verdict.find("leaky (5 intersections"), std::string::npos) << missed.verdict;
  EXPECT_TRUE(results_table(hand_scene(), {none}).verdict.empty());

  // A fragment that vanishes fails the goals as a cut does: the clean run with one vanished
  // fragment is no longer best; with less deviation it still loses to one that keeps them all.
  Evaluation faded = clean;
  faded.summary.strategy = "faded";
  faded.summary.intersections.vanished_fragments = 1;
  faded.summary.deviation.mean_m = 0.0;
  const ResultsTable both = results_table(hand_scene(), {none, faded, clean});
  ASSERT_TRUE(both.best_row);
  EXPECT_EQ(*both.best_row, 2u);
  const ResultsTable alone = results_table(hand_scene(), {none, faded});
  EXPECT_FALSE(alone.best_row);
  EXPECT_NE(alone.verdict.find("faded (1 intersections or vanished"), std::string::npos)
      << alone.verdict;
  EXPECT_EQ(alone.rows[1][4], "1");
}

TEST(ResultsTable, EscapesAndQuotesNames) {
  const ResultsTable table = results_table(hand_scene(), {hand_run("a<b>,\"c\"")});
  EXPECT_NE(results_html(table).find("<td>a&lt;b&gt;,&quot;c&quot;</td>"), std::string::npos);
  EXPECT_EQ(lines(results_csv(table, false))[1].rfind("\"a<b>,\"\"c\"\"\",3,", 0), 0u);
}

}  // namespace
}  // namespace fragsim
