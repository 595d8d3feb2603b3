// fragsim suite: the battery's size and combinations, the aggregation and the recommendation on
// hand-made results. The command end to end is in tests/cli/suite_command_test.cpp.

#include "experiments/suite.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>

#include "sim/scene_strategies.hpp"

namespace fragsim {
namespace {

const std::string kSceneDir = std::string(FRAGSIM_DATA_DIR) + "/scenes";

TEST(Suite, DefaultSeedsGiveAtLeastAThousandRunsOfEveryCombination) {
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

TEST(Suite, ModesSetTheCameraKeys) {
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

TEST(Suite, EveryStrategyIsARowAndEdgeMinOncePerCameraModel) {
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

TEST(Suite, EveryEntryModeAndVariantIsAValidScene) {
  const std::vector<SuiteRun> runs = suite_runs({});
  const auto scenes = load_suite_scenes(kSceneDir, runs);
  EXPECT_EQ(scenes.size(), 5u);
  EXPECT_NO_THROW(validate_suite(scenes, runs, suite_variants()));
}

TEST(Suite, SelectionFiltersKeepBatteryOrder) {
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

TEST(Suite, CleanShareMeansAndKeptNearMisses) {
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

TEST(Suite, KeepSelectsRunsAndEvenMediansAverage) {
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

TEST(Suite, NoNearMissesToKeepIsNotAShare) {
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

TEST(Suite, PlayerShareThenAllRunsThenDeviation) {
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

TEST(Suite, WithoutPlayerRunsAllRunsDecide) {
  const std::vector<SuiteRow> all{row("none", 4, 1, 0.0), row("A", 4, 3, 0.1), row("B", 4, 4, 5.0)};
  const auto best = recommend_suite({}, all);
  ASSERT_TRUE(best);
  EXPECT_EQ(best->variant, "B");
  EXPECT_FALSE(best->player_clean_share.has_value());
  EXPECT_FALSE(recommend_suite({}, {row("none", 4, 1, 0.0)}).has_value());
}

TEST(Suite, OneRowPerRunAndVariantWithTheEntryFields) {
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

TEST(Suite, ReadsBackTheRunsAndOutcomesSuiteCsvWrote) {
  const std::vector<SuiteRun> runs = {{"front", "6", "future", "10", "path", 1},
                                      {"front", "6", "future", "10", "path", 2},
                                      {"close", "1.5", "present", "9", "player", 2}};
  std::vector<SuiteOutcome> outcomes;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    for (const char* v : {"none", "edge"}) {
      SuiteOutcome o;
      o.run = r;
      o.variant = v;
      o.near_fragments = static_cast<int>(r);
      o.camera_hits = 1;
      o.deviation_mean_m = 0.1 * static_cast<double>(r) + 1e-17;
      o.near_misses = 7;
      o.strategy_ms_median = 0.003;
      outcomes.push_back(o);
    }
  }
  const std::string csv = suite_csv(runs, outcomes);
  const SuiteTable t = read_suite_csv(csv);
  ASSERT_EQ(t.runs.size(), 3u);
  EXPECT_EQ(t.variants, 2u);
  EXPECT_EQ(t.runs[2].scene, "close");
  EXPECT_EQ(t.runs[1].seed, 2u);
  ASSERT_EQ(t.outcomes.size(), 6u);
  EXPECT_EQ(t.outcomes[5].run, 2u);
  EXPECT_EQ(suite_csv(t.runs, t.outcomes), csv);  // every number back to its last bit
  EXPECT_THROW(read_suite_csv("a,b\n"), std::runtime_error);
  EXPECT_THROW(read_suite_csv(csv + "front,6\n"), std::runtime_error);
}

}  // namespace
}  // namespace fragsim
