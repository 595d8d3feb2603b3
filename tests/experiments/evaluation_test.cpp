// Evaluating strategies on the shipped scenes: `none` as its own reference deviates by exactly
// zero, a zero-gain edge is `none`, worker processes give the one-process results, and the
// thesis's goals and the z-fighting flag on hand-made summaries.

#include "experiments/evaluation.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "metrics/trajectory_record.hpp"
#include "report/csv_export.hpp"
#include "sim/scene_file.hpp"
#include "support/shipped_scene.hpp"

namespace fragsim {
namespace {

using test::scene_named;

TEST(Evaluation, NoneAgainstItselfDeviatesExactlyZero) {
  const Scene scene = scene_named("thesis125");
  TrajectoryRecord ref;
  EvaluationOptions rec_opts;
  rec_opts.record = &ref;
  evaluate(scene, "none", rec_opts);
  EvaluationOptions opts;
  opts.reference = &ref;
  const RunSummary s = evaluate(scene, "none", opts).summary;
  EXPECT_EQ(s.deviation.max_m, 0.0);
  EXPECT_EQ(s.deviation.deviated_share, 0.0);
}

TEST(Evaluation, ZeroGainEdgeReproducesNoneExactly) {
  Scene scene = scene_named("front");
  scene.strategies.edge.k = 0.0;
  const auto runs = compare(scene, {"none", "edge"}, false);
  ASSERT_EQ(runs.size(), 2u);
  EXPECT_EQ(runs[1].summary.deviation.max_m, 0.0);
  EXPECT_EQ(runs[1].summary.intersections.near_fragments,
            runs[0].summary.intersections.near_fragments);
  EXPECT_EQ(runs[1].near_per_step, runs[0].near_per_step);
  EXPECT_GT(runs[1].summary.activity.candidates_initial, 0);  // it predicted, it just did not push
}

TEST(Evaluation, BestForThesisGoalsPrefersNoIntersectionsThenLeastDeviation) {
  std::vector<Evaluation> runs(4);
  runs[0].summary.strategy = "none";
  runs[1].summary.strategy = "a";
  runs[1].summary.intersections.near_fragments = 1;
  runs[2].summary.strategy = "b";
  runs[2].summary.deviation.mean_m = 0.5;
  runs[3].summary.strategy = "c";
  runs[3].summary.deviation.mean_m = 0.2;
  const auto best = best_for_thesis_goals(runs);
  ASSERT_TRUE(best.has_value());
  EXPECT_EQ(*best, 3u);
}

TEST(Evaluation, WorkerProcessesGiveTheSameResultsAsOneProcess) {
  const Scene scene = load_scene(std::string(FRAGSIM_DATA_DIR) + "/scenes/thesis125.ini");
  const std::vector<std::string> all{"none",       "wall", "deflect-all",
                                     "near-plane", "edge", "edge-min"};
  const auto one = compare(scene, all, true, nullptr, 1);
  const auto two = compare(scene, all, true, nullptr, 2);
  const auto six = compare(scene, all, true, nullptr, 6);
  EXPECT_EQ(summary_csv(scene, one), summary_csv(scene, two));
  EXPECT_EQ(steps_csv(scene, one), steps_csv(scene, two));
  EXPECT_EQ(camera_csv(scene, one), camera_csv(scene, two));
  EXPECT_EQ(summary_csv(scene, one), summary_csv(scene, six));
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].physics_s_per_step.size(), two[i].physics_s_per_step.size());
  }
}

TEST(Evaluation, BestForThesisGoalsCountsEveryFailureAlikeAndBreaksTiesByNearMisses) {
  std::vector<Evaluation> runs(4);
  runs[0].summary.strategy = "none";  // never the best, however good
  runs[1].summary.strategy = "cam";
  runs[1].summary.intersections.camera_hit_fragments = 1;
  runs[2].summary.strategy = "fade";
  runs[2].summary.intersections.vanished_fragments = 1;
  runs[3].summary.strategy = "near";
  runs[3].summary.intersections.near_fragments = 1;
  runs[3].summary.intersections.near_misses = 5;
  // One failure each and the same deviation: the most near misses wins.
  EXPECT_EQ(best_for_thesis_goals(runs), std::optional<std::size_t>(3));
  runs[3].summary.intersections.near_misses = 0;  // all tied: the first named
  EXPECT_EQ(best_for_thesis_goals(runs), std::optional<std::size_t>(1));
  runs[2].summary.intersections.vanished_fragments = 0;  // no failure beats any deviation
  runs[2].summary.deviation.mean_m = 100.0;
  EXPECT_EQ(best_for_thesis_goals(runs), std::optional<std::size_t>(2));
  EXPECT_EQ(best_for_thesis_goals({runs[0]}), std::nullopt);
  EXPECT_EQ(best_for_thesis_goals({}), std::nullopt);
}

TEST(Evaluation, ZFightingIsADepthStepAboveAThousandthOfTheDistance) {
  RunSummary s;
  s.activity.depth_step_m = 0.0101;
  EXPECT_TRUE(z_fighting(s, 10.0));
  s.activity.depth_step_m = 0.0099;
  EXPECT_FALSE(z_fighting(s, 10.0));
  s.activity.depth_step_m = 0.0;  // no near distance recorded
  EXPECT_FALSE(z_fighting(s, 10.0));
}

}  // namespace
}  // namespace fragsim
