// fragsim suite: the battery's size and combinations, the aggregation and the recommendation on
// hand-made results, and the command end to end (a slice gives the same CSV for any --jobs; bad
// input is one line and status 2).

#include "experiments/suite.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>

#include "sim/scene_strategies.hpp"
#include "support/run_fragsim.hpp"

namespace fragsim {
namespace {

const std::string kSceneDir = std::string(FRAGSIM_DATA_DIR) + "/scenes";

TEST(SuiteBattery, DefaultSeedsGiveAtLeastAThousandRunsOfEveryCombination) {
  const std::vector<SuiteRun> runs = suite_runs({});
  // 5 scenes x 2 distances x 2 aims x 2 speeds x 4 camera modes x 9 seeds.
  EXPECT_EQ(runs.size(), 1440u);
  EXPECT_GE(runs.size(), 1000u);
  std::set<std::string> scenes, aims, modes;
  std::set<
      std::tuple<std::string, std::string, std::string, std::string, std::string, std::uint64_t>>
      distinct;
  for (const SuiteRun& r : runs) {
    scenes.insert(r.scene);
    aims.insert(r.aim);
    modes.insert(r.mode);
    distinct.insert({r.scene, r.distance_m, r.aim, r.toward_camera_mps, r.mode, r.seed});
  }
  EXPECT_EQ(distinct.size(), runs.size());  // no run twice
  EXPECT_EQ(scenes,
            (std::set<std::string>{"front", "thesis125", "thesis1000", "close", "distance"}));
  EXPECT_EQ(aims, (std::set<std::string>{"future", "present"}));
  EXPECT_EQ(modes, (std::set<std::string>{"path", "player", "player-instant", "player-flick"}));
  // Seeds 1..9 under every entry and mode, the seed turning fastest.
  for (std::size_t i = 0; i < runs.size(); ++i) EXPECT_EQ(runs[i].seed, i % 9 + 1);
  EXPECT_EQ(runs.front().scene, "front");
  EXPECT_EQ(runs.back().scene, "distance");
}

TEST(SuiteBattery, ModesSetTheCameraKeys) {
  auto keys = [](const SuiteRun& r) {
    std::map<std::string, std::string> m;
    for (const SceneOverride& o : suite_overrides(r)) m[o.key] = o.value;
    return m;
  };
  SuiteRun r{"front", "6", "present", "15", "player-instant", 4};
  auto k = keys(r);
  EXPECT_EQ(k["camera.mode"], "player");
  EXPECT_EQ(k["camera.player_accel_mps2"], "inf");
  EXPECT_EQ(k["object.distance_m"], "6");
  EXPECT_EQ(k["explosion.aim"], "present");
  EXPECT_EQ(k["explosion.toward_camera_mps"], "15");
  EXPECT_EQ(k["simulation.seed"], "4");
  r.mode = "player";
  k = keys(r);
  EXPECT_EQ(k["camera.mode"], "player");
  EXPECT_EQ(k.count("camera.player_accel_mps2"), 0u);  // the scene's default acceleration
  r.mode = "player-flick";
  k = keys(r);
  EXPECT_EQ(k["camera.mode"], "player");
  EXPECT_EQ(k["camera.turn_rate_degps"], "720");
  EXPECT_EQ(k.count("camera.player_accel_mps2"), 0u);
  r.mode = "path";
  EXPECT_EQ(keys(r)["camera.mode"], "path");
  EXPECT_TRUE(is_player_mode("player"));
  EXPECT_TRUE(is_player_mode("player-instant"));
  EXPECT_TRUE(is_player_mode("player-flick"));
  EXPECT_FALSE(is_player_mode("path"));
}

TEST(SuiteBattery, EveryStrategyIsARowAndEdgeMinOncePerCameraModel) {
  const std::vector<SuiteVariant> v = suite_variants();
  ASSERT_FALSE(v.empty());
  EXPECT_EQ(v.front().label, "none");
  std::set<std::string> strategies, labels;
  for (const SuiteVariant& x : v) {
    strategies.insert(x.strategy);
    labels.insert(x.label);
  }
  for (const std::string& n : strategy_names()) EXPECT_EQ(strategies.count(n), 1u) << n;
  for (const char* model : {"constant", "bounded_accel", "reachable"}) {
    EXPECT_EQ(labels.count(std::string("edge-min/") + model), 1u) << model;
  }
  EXPECT_EQ(labels.count("edge-min"), 0u);  // only under a camera model
  EXPECT_EQ(labels.size(), v.size());
}

TEST(SuiteBattery, EveryEntryModeAndVariantIsAValidScene) {
  const std::vector<SuiteRun> runs = suite_runs({});
  const auto scenes = load_suite_scenes(kSceneDir, runs);
  EXPECT_EQ(scenes.size(), 5u);
  EXPECT_NO_THROW(validate_suite(scenes, runs, suite_variants()));
}

TEST(SuiteBattery, SelectionFiltersKeepBatteryOrder) {
  SuiteSelection sel;
  sel.scenes = {"close", "thesis125"};  // listed out of table order
  sel.modes = {"path"};
  sel.seeds = 1;
  const std::vector<SuiteRun> runs = suite_runs(sel);
  ASSERT_EQ(runs.size(), 16u);  // 2 scenes x 2 distances x 2 aims x 2 speeds
  EXPECT_EQ(runs.front().scene, "thesis125");
  EXPECT_EQ(runs.back().scene, "close");
  sel.limit = 2;
  EXPECT_EQ(suite_runs(sel).size(), 2u);
  sel.scenes = {"nowhere"};
  EXPECT_THROW(suite_runs(sel), SuiteError);
  sel.scenes = {};
  sel.modes = {"drone"};
  EXPECT_THROW(suite_runs(sel), SuiteError);
  sel.modes = {};
  sel.seeds = 0;
  EXPECT_THROW(suite_runs(sel), SuiteError);
}

SuiteOutcome outcome(std::size_t run, const std::string& variant, int near, int cam, double dev,
                     int misses, double ms) {
  SuiteOutcome o;
  o.run = run;
  o.variant = variant;
  o.near_fragments = near;
  o.camera_hits = cam;
  o.deviation_mean_m = dev;
  o.near_misses = misses;
  o.strategy_ms_median = ms;
  return o;
}

// Three runs, two variants: numbers worked out by hand below.
std::vector<SuiteOutcome> hand_made() {
  return {
      outcome(0, "none", 2, 1, 0.0, 10, 0.0), outcome(0, "edge", 0, 0, 0.5, 6, 0.2),
      outcome(1, "none", 0, 0, 0.0, 4, 0.0),  outcome(1, "edge", 0, 1, 1.5, 1, 0.4),
      outcome(2, "none", 1, 0, 0.0, 6, 0.0),  outcome(2, "edge", 0, 0, 1.0, 5, 0.3),
  };
}

TEST(SuiteAggregation, CleanShareMeansAndKeptNearMisses) {
  const std::vector<SuiteRow> rows = aggregate_suite(hand_made());
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].variant, "none");
  EXPECT_EQ(rows[0].runs, 3);
  EXPECT_EQ(rows[0].clean_runs, 1);  // only run 1
  EXPECT_DOUBLE_EQ(rows[0].clean_share(), 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(*rows[0].near_misses_kept(), 1.0);
  const SuiteRow& edge = rows[1];
  EXPECT_EQ(edge.variant, "edge");
  EXPECT_EQ(edge.runs, 3);
  EXPECT_EQ(edge.clean_runs, 2);                    // runs 0 and 2 (run 1 hit the camera)
  EXPECT_DOUBLE_EQ(edge.deviation_mean_m, 1.0);     // (0.5 + 1.5 + 1.0) / 3
  EXPECT_EQ(edge.near_misses, 12);                  // 6 + 1 + 5
  EXPECT_EQ(edge.none_near_misses, 20);             // 10 + 4 + 6
  EXPECT_DOUBLE_EQ(*edge.near_misses_kept(), 0.6);  // 12 / 20
  EXPECT_DOUBLE_EQ(edge.strategy_ms_median, 0.3);   // median of 0.2, 0.4, 0.3
}

TEST(SuiteAggregation, KeepSelectsRunsAndEvenMediansAverage) {
  const std::vector<SuiteRow> rows =
      aggregate_suite(hand_made(), [](std::size_t run) { return run <= 1; });
  ASSERT_EQ(rows.size(), 2u);
  const SuiteRow& edge = rows[1];
  EXPECT_EQ(edge.runs, 2);
  EXPECT_EQ(edge.clean_runs, 1);
  EXPECT_DOUBLE_EQ(edge.deviation_mean_m, 1.0);     // (0.5 + 1.5) / 2
  EXPECT_DOUBLE_EQ(*edge.near_misses_kept(), 0.5);  // 7 / 14
  EXPECT_DOUBLE_EQ(edge.strategy_ms_median, 0.5 * (0.2 + 0.4));
  EXPECT_TRUE(aggregate_suite(hand_made(), [](std::size_t) { return false; }).empty());
}

TEST(SuiteAggregation, NoNearMissesToKeepIsNotAShare) {
  const std::vector<SuiteRow> rows = aggregate_suite(
      {outcome(0, "none", 0, 0, 0.0, 0, 0.0), outcome(0, "wall", 0, 0, 0.1, 0, 0.0)});
  EXPECT_FALSE(rows[1].near_misses_kept().has_value());
}

SuiteRow row(const std::string& variant, int runs, int clean, double dev) {
  SuiteRow r;
  r.variant = variant;
  r.runs = runs;
  r.clean_runs = clean;
  r.deviation_mean_m = dev;
  return r;
}

TEST(SuiteRecommendation, PlayerShareThenAllRunsThenDeviation) {
  // none is never recommended, even when cleanest. B and C tie on the player runs; C is cleaner
  // over all runs, though A deviates least and B less than C.
  const std::vector<SuiteRow> player{row("none", 10, 10, 0.0), row("A", 10, 8, 0.1),
                                     row("B", 10, 9, 0.5), row("C", 10, 9, 2.0)};
  const std::vector<SuiteRow> all{row("none", 20, 20, 0.0), row("A", 20, 19, 0.1),
                                  row("B", 20, 15, 0.5), row("C", 20, 18, 2.0)};
  auto best = recommend_suite(player, all);
  ASSERT_TRUE(best);
  EXPECT_EQ(best->variant, "C");
  EXPECT_DOUBLE_EQ(*best->player_clean_share, 0.9);
  EXPECT_DOUBLE_EQ(best->all_clean_share, 0.9);
  EXPECT_DOUBLE_EQ(best->deviation_mean_m, 2.0);

  // Tied on both shares: the least deviation wins.
  const std::vector<SuiteRow> all_tied{row("A", 20, 19, 0.1), row("B", 20, 18, 0.5),
                                       row("C", 20, 18, 0.4)};
  EXPECT_EQ(recommend_suite(player, all_tied)->variant, "C");
  // Tied on everything: the earlier row.
  const std::vector<SuiteRow> same{row("B", 20, 18, 0.4), row("C", 20, 18, 0.4)};
  EXPECT_EQ(recommend_suite(player, same)->variant, "B");
}

TEST(SuiteRecommendation, WithoutPlayerRunsAllRunsDecide) {
  const std::vector<SuiteRow> all{row("none", 4, 1, 0.0), row("A", 4, 3, 0.1), row("B", 4, 4, 5.0)};
  const auto best = recommend_suite({}, all);
  ASSERT_TRUE(best);
  EXPECT_EQ(best->variant, "B");
  EXPECT_FALSE(best->player_clean_share.has_value());
  EXPECT_FALSE(recommend_suite({}, {row("none", 4, 1, 0.0)}).has_value());
}

TEST(SuiteCsv, OneRowPerRunAndVariantWithTheEntryFields) {
  const std::vector<SuiteRun> runs{{"close", "1.5", "future", "6", "path", 1},
                                   {"close", "1.5", "future", "6", "player", 1},
                                   {"close", "2.2", "present", "9", "player-instant", 3}};
  const std::string csv = suite_csv(runs, hand_made());
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line,
            "scene,object.distance_m,explosion.aim,explosion.toward_camera_mps,seed,mode,strategy,"
            "near_fragments,camera_hit_fragments,vanished_fragments,deviation_mean_m,near_misses,"
            "strategy_ms_median");
  std::getline(in, line);
  EXPECT_EQ(line, "close,1.5,future,6,1,path,none,2,1,0,0,10,0");
  std::getline(in, line);
  EXPECT_EQ(line, "close,1.5,future,6,1,path,edge,0,0,0,0.5,6,0.2");
  int rows = 2;
  while (std::getline(in, line)) {
    ++rows;
    if (rows == 5) {
      EXPECT_EQ(line, "close,2.2,present,9,3,player-instant,none,1,0,0,0,6,0");
    }
  }
  EXPECT_EQ(rows, 6);
}

// ---- The command, end to end. ----

int lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

std::string read(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The CSV without its last column, strategy_ms_median: the only one that is a timing.
std::string without_timing(const std::string& csv) {
  std::istringstream in(csv);
  std::string out, line;
  while (std::getline(in, line)) out += line.substr(0, line.rfind(',')) + "\n";
  return out;
}

std::string slice_args(const std::string& out, int jobs) {
  // 2 entries x 1 seed: thesis125 at 4 m, aim future, speeds 3 and 6 m/s, path camera.
  return "suite --scene-dir " + kSceneDir +
         " --scenes thesis125 --modes path --seeds 1 --limit 2 --jobs " + std::to_string(jobs) +
         " --force --out " + out;
}

TEST(SuiteCommand, SliceGivesTheSameCsvForAnyJobs) {
  const std::string a = ::testing::TempDir() + "/fragsim_suite_j1.csv";
  const std::string b = ::testing::TempDir() + "/fragsim_suite_j2.csv";
  const test::Result r1 = test::run_fragsim(slice_args(a, 1));
  const test::Result r2 = test::run_fragsim(slice_args(b, 2));
  ASSERT_EQ(r1.status, 0) << r1.out;
  ASSERT_EQ(r2.status, 0) << r2.out;
  const std::string ca = read(a), cb = read(b);
  EXPECT_EQ(lines(ca), 1 + 2 * static_cast<int>(suite_variants().size()));
  EXPECT_EQ(without_timing(ca), without_timing(cb));
  EXPECT_NE(r1.out.find("mode path"), std::string::npos) << r1.out;
  EXPECT_NE(r1.out.find("most robust"), std::string::npos) << r1.out;
  EXPECT_NE(ca.find("thesis125,4,future,3,1,path,edge-min/reachable,"), std::string::npos) << ca;
  EXPECT_NE(ca.find("thesis125,4,future,6,1,path,none,"), std::string::npos) << ca;
}

void expect_usage_error(const std::string& args, const std::string& option) {
  const test::Result r = test::run_fragsim(args);
  EXPECT_EQ(r.status, 2) << args << ": " << r.out;
  EXPECT_EQ(lines(r.out), 1) << args << ": " << r.out;
  EXPECT_NE(r.out.find(option), std::string::npos) << args << ": " << r.out;
}

TEST(SuiteCommand, BadInputIsOneLineNamingTheOption) {
  expect_usage_error("suite --frobnicate", "--frobnicate");
  expect_usage_error("suite front", "'front'");
  expect_usage_error("suite --seeds 0", "--seeds");
  expect_usage_error("suite --seeds many", "--seeds");
  expect_usage_error("suite --scenes nowhere", "--scenes");
  expect_usage_error("suite --modes drone", "--modes");
  expect_usage_error("suite --jobs 0", "--jobs");
  expect_usage_error("suite --limit 0", "--limit");
  expect_usage_error("suite --scene-dir /nonexistent/scenes", "--scene-dir");
  expect_usage_error("suite --scene-dir " + kSceneDir + " --out /nonexistent/dir/suite.csv",
                     "--out");
}

TEST(SuiteCommand, HelpListsTheOptions) {
  const test::Result r = test::run_fragsim("suite --help");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("--seeds"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("1440 runs"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace fragsim
