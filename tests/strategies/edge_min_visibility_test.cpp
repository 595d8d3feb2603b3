// edge-min's two visibility options (docs/visibility.md): the exit edges a director weighs
// (edge_weights) and the occlusion bound on the central region (cover_max).

#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "control/strategies/edge_min_strategy.hpp"
#include "experiments/evaluation.hpp"
#include "io/input_error.hpp"
#include "settings/key.hpp"
#include "sim/scene_file.hpp"
#include "strategies/registry.hpp"
#include "support/test_scenes.hpp"

namespace fragsim {
namespace {

constexpr double kDt = 1.0 / 60.0;

// The fragment of edge_min_strategy_test fired at the lens from 2 cm above the axis, 1 cm to
// the right: protected box 0.2 + r to the sides, 0.15 + r up and down (r = 0.0866 m), so the
// ways out need top 0.2166 m, bottom 0.2566, right 0.2766, left 0.2966 m of sideways travel.
Scene at_the_lens(const std::array<double, 4>& weights) {
  Scene scene = test::single_fragment({0.01, 1.62, -10.0});
  scene.strategies.edge_min.camera_model = CameraModel::kConstant;
  scene.strategies.edge_min.edge_weights = weights;
  return scene;
}

// Every push of the run, summed: which way it went.
Eigen::Vector3d total_push(const test::RecordedRun& o) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const auto& step : o.rec.steps) {
    for (const AppliedForce& f : step.forces) sum += f.force_N;
  }
  return sum;
}

TEST(EdgeMinVisibility, EqualWeightsTakeTheNearestEdgeTheTop) {
  const auto o = test::run_recorded(at_the_lens({1, 1, 1, 1}), "edge-min");
  EXPECT_GT(total_push(o).y(), 0.0);
  EXPECT_EQ(total_push(o).x(), 0.0);
  EXPECT_EQ(o.summary.activity.forced_fragments, 1);
  EXPECT_EQ(o.summary.pushed_exits.top, 1);
  EXPECT_EQ(o.summary.intersections.camera_hit_fragments, 0);
}

TEST(EdgeMinVisibility, ForbiddenTopSendsTheFragmentOutThroughTheBottom) {
  // Top forbidden: of the others the bottom needs least (0.2566 m against 0.2766 and 0.2966).
  const auto o = test::run_recorded(at_the_lens({0, 1, 1, 1}), "edge-min");
  for (const auto& step : o.rec.steps) {
    for (const AppliedForce& f : step.forces) EXPECT_LT(f.force_N.y(), 0.0);
  }
  EXPECT_EQ(o.summary.pushed_exits.top, 0);
  EXPECT_EQ(o.summary.pushed_exits.bottom, 1);
  EXPECT_EQ(o.summary.intersections.near_fragments, 0);
  EXPECT_EQ(o.summary.intersections.camera_hit_fragments, 0);
}

TEST(EdgeMinVisibility, OnlyTheSidesSendItRightTheNearerSide) {
  const auto o = test::run_recorded(at_the_lens({0, 0, 1, 1}), "edge-min");
  EXPECT_GT(total_push(o).x(), 0.0);
  EXPECT_EQ(total_push(o).y(), 0.0);
  EXPECT_EQ(o.summary.pushed_exits.right, 1);
  EXPECT_EQ(o.summary.intersections.camera_hit_fragments, 0);
}

TEST(EdgeMinVisibility, AHeavierWeightBuysAFartherEdge) {
  // Left needs 0.2966 / 0.2166 = 1.37 times the top's push: a weight of 2 on the left wins.
  const auto o = test::run_recorded(at_the_lens({1, 1, 2, 1}), "edge-min");
  EXPECT_LT(total_push(o).x(), 0.0);
  EXPECT_EQ(o.summary.pushed_exits.left, 1);
  // And a weight of 1.2 does not (1.37 > 1.2): still the top.
  const auto p = test::run_recorded(at_the_lens({1, 1, 1.2, 1}), "edge-min");
  EXPECT_GT(total_push(p).y(), 0.0);
  EXPECT_EQ(p.summary.pushed_exits.top, 1);
}

// Equal weights other than 1 go through the weighted rule, which must then be the least push:
// every force of every step of a 125-fragment scene, bit for bit, against the default weights.
TEST(EdgeMinVisibility, EqualWeightsGiveBitIdenticalForces) {
  Scene scene = load_scene(std::string(FRAGSIM_DATA_DIR) + "/scenes/thesis125.ini");
  const auto a = test::run_recorded(scene, "edge-min");
  scene.strategies.edge_min.edge_weights = {2.5, 2.5, 2.5, 2.5};
  const auto b = test::run_recorded(scene, "edge-min");
  ASSERT_EQ(a.rec.steps.size(), b.rec.steps.size());
  int forces = 0;
  for (std::size_t k = 0; k < a.rec.steps.size(); ++k) {
    ASSERT_EQ(a.rec.steps[k].forces.size(), b.rec.steps[k].forces.size()) << "step " << k;
    for (std::size_t j = 0; j < a.rec.steps[k].forces.size(); ++j) {
      EXPECT_EQ(a.rec.steps[k].forces[j].fragment, b.rec.steps[k].forces[j].fragment);
      EXPECT_EQ(a.rec.steps[k].forces[j].force_N, b.rec.steps[k].forces[j].force_N);
      ++forces;
    }
  }
  EXPECT_GT(forces, 0);
}

// The keys' rules, with the one-line message naming the key.
std::string message_for(const std::string& key, const std::string& value) {
  const StrategyEntry* e = find_strategy("edge-min");
  EXPECT_NE(e, nullptr);
  StrategySettings settings;
  try {
    for (const auto& k : e->keys) {
      if (k.name == "edge-min." + key) settings::apply(k, settings, value, "--edge-min." + key);
    }
  } catch (const InputError& err) {
    return err.what();
  }
  return "";
}

TEST(EdgeMinVisibility, RangesAreChecked) {
  EXPECT_EQ(message_for("edge_weights", "1 2 0 4"), "");
  EXPECT_EQ(message_for("cover_max", "0.5"), "");
  for (const auto& [key, bad] :
       std::vector<std::pair<std::string, std::string>>{{"edge_weights", "0 0 0 0"},
                                                        {"edge_weights", "1 1 -1 1"},
                                                        {"edge_weights", "1 1 inf 1"},
                                                        {"edge_weights", "1 nan 1 1"},
                                                        {"edge_weights", "1 1 1"},
                                                        {"edge_weights", "1 1 1 1 1"},
                                                        {"cover_max", "1.5"},
                                                        {"cover_max", "-0.1"},
                                                        {"cover_max", "nan"},
                                                        {"cover_region", "0"},
                                                        {"cover_horizon_s", "0"},
                                                        {"cover_horizon_s", "inf"},
                                                        {"cover_samples", "0"},
                                                        {"cover_cells", "1"},
                                                        {"cover_margin", "0.6"},
                                                        {"cover_margin", "-0.01"}}) {
    const std::string m = message_for(key, bad);
    EXPECT_NE(m.find("edge-min." + key), std::string::npos) << key << " = " << bad << ": " << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
}

// A wall of 60 boxes (0.12 m, 10 x 6 at 0.1 m spacing) 5 m ahead of a still camera, coming at
// 4 m/s with no gravity: at 1 m depth it spans 1.07 x 0.67 m, over the central region's 1.03 x 0.58
// m (half the screen's width and height at fovy 60, aspect 16:9), so the predicted coverage must
// reach all of the region within the horizon; with cover_max = 0.5 every predicted sample
// the pushes can reach must end at most 0.5 - cover_margin covered (the grid is counted
// exactly: tolerance 0).
std::vector<FragmentState> wall_of_boxes(double depth_m, double speed_mps) {
  std::vector<FragmentState> out;
  for (int i = 0; i < 10; ++i) {
    for (int j = 0; j < 6; ++j) {
      FragmentState f;
      f.position_m = {-0.45 + 0.1 * i, -0.25 + 0.1 * j, -depth_m};
      f.velocity_mps = {0.0, 0.0, speed_mps};
      f.half_extents_m = {0.06, 0.06, 0.06};
      f.radius_m = 0.104;
      f.mass_kg = 0.6;
      out.push_back(f);
    }
  }
  return out;
}

StepContext still_camera(std::span<const FragmentState> fragments) {
  StepContext ctx;
  ctx.dt_s = kDt;
  ctx.camera.aspect = 16.0 / 9.0;
  ctx.camera_max_speed_mps = 3.0;
  ctx.camera_body_half_m = {0.15, 0.1, 0.15};
  ctx.fragments = fragments;
  return ctx;
}

// A horizon of a billion steps (cover_horizon_s = 10 at dt = 1e-8 s) is sampled band by band: with
// B = 12, 23 samples at stride 1, then 12 per doubling of the stride up to 1e9 steps (about 26
// doublings), so a few hundred samples, the last at the horizon, and no loop over every step (it
// hung before, found by the scene keys' property test).
TEST(EdgeMinVisibility, ALongHorizonAtATinyStepIsSampledByBands) {
  const std::vector<FragmentState> wall = wall_of_boxes(5.0, 4.0);
  EdgeMinParams p;
  p.cover_max = 0.5;
  p.cover_horizon_s = 10.0;
  OcclusionBound b;
  b.reset(static_cast<int>(wall.size()));
  StepOutput out;
  StepContext ctx = still_camera(wall);
  ctx.dt_s = 1e-8;
  b.step(ctx, p, {1.0, 1.0, 1.0, 1.0}, out);
  EXPECT_GT(b.sample_times_s().size(), 23u + 12u * 20u);
  EXPECT_LT(b.sample_times_s().size(), 23u + 12u * 30u);
  EXPECT_NEAR(b.sample_times_s().front(), 1e-8, 1e-20);
  EXPECT_LE(b.sample_times_s().back(), 10.0 + 1e-12);
  EXPECT_GT(b.sample_times_s().back(), 8.0);  // the last band's stride is 2^26 steps, 0.67 s
}

TEST(EdgeMinVisibility, PredictedCoverageOfAWallStaysUnderTheBound) {
  // The bound alone, without edge-min's push against the camera (which would already move the
  // middle of the wall aside), so the wall's coverage is the plain prediction.
  const std::vector<FragmentState> wall = wall_of_boxes(5.0, 4.0);
  EdgeMinParams p;
  p.cover_max = 0.5;
  OcclusionBound b;
  b.reset(static_cast<int>(wall.size()));
  StepOutput out;
  b.step(still_camera(wall), p, {1.0, 1.0, 1.0, 1.0}, out);
  // At step 0 with B = 12: steps 1..23 ahead (23), the even ones of 24..46 (12) and the
  // multiples of 4 of 48..60 (4); one step ahead first, the horizon (1 s, 60 steps) last: the
  // wall is then at 1 m.
  ASSERT_EQ(b.sample_times_s().size(), 39u);
  EXPECT_NEAR(b.sample_times_s().front(), kDt, 1e-12);
  EXPECT_NEAR(b.sample_times_s().back(), 1.0, 1e-12);
  // Before: the wall at 1 m covers all the region. Its boxes (0.12 m) are drawn as discs of
  // r = sqrt(6 0.06^2 / pi) = 0.083 m, more than the 0.0707 m from a square of four centres to
  // its middle, so there are no holes, and it spans 1.07 x 0.67 m, more than the 1.03 x 0.58 m.
  EXPECT_GT(b.predicted_before().back(), 0.99);
  // At 5 m (one step later, 4.93 m) it covers those 1.07 x 0.67 m of the region's 5.1 x 2.9 m:
  // about 5%.
  EXPECT_NEAR(b.predicted_before().front(), 0.05, 0.02);
  // The prediction aims cover_margin (0.03) under the bound.
  for (std::size_t j = 0; j < b.predicted_after().size(); ++j) {
    EXPECT_LE(b.predicted_after()[j], 0.5 - 0.03) << "sample " << j;
  }
  EXPECT_GT(b.pushed(), 0);
  EXPECT_FALSE(out.forces.empty());
  // Each push is sideways (in the screen plane) and within a_max.
  for (const AppliedForce& f : out.forces) {
    EXPECT_EQ(f.force_N.z(), 0.0);
    EXPECT_LE(f.force_N.norm(), 0.6 * p.a_max_mps2 * (1 + 1e-12));
  }
}

TEST(EdgeMinVisibility, OffPredictsNothingAndPushesNothingExtra) {
  const std::vector<FragmentState> wall = wall_of_boxes(5.0, 4.0);
  EdgeMinParams p;
  p.camera_model = CameraModel::kConstant;
  EdgeMinStrategy off(p);
  off.reset(static_cast<int>(wall.size()));
  StepOutput out;
  off.step(still_camera(wall), out);
  EXPECT_TRUE(off.occlusion_bound().predicted_before().empty());
  // Only the fragments aimed at the protected box are pushed (those within 0.2 + r sideways and
  // 0.15 + r up and down of the axis).
  for (const AppliedForce& f : out.forces) {
    const Eigen::Vector3d& q = wall[static_cast<std::size_t>(f.fragment)].position_m;
    EXPECT_LE(std::abs(q.x()), 0.2 + 0.0866 + 0.05 + 1e-9);
    EXPECT_LE(std::abs(q.y()), 0.15 + 0.0866 + 0.05 + 1e-9);
  }
}

// A wall simulated: a 0.6 m cube of 6^3 boxes of 0.1 m coming at 4 m/s from 5 m. The
// metric's central occlusion, which the bound predicts with discs on a coarse grid, ends near
// the bound where without control the block covers all the centre.
TEST(EdgeMinVisibility, MeasuredCentralOcclusionFollowsTheBound) {
  Scene scene = test::single_fragment({0.0, 1.6, -5.0}, 0.0);
  scene.object.size_m = 0.6;
  scene.object.splits = 6;
  scene.explosion.toward_camera_mps = 4.0;
  scene.sim.duration_s = 1.5;
  const RunSummary none = evaluate(scene, "none", {}).summary;
  EXPECT_GT(none.occlusion.central_max, 0.9);
  scene.strategies.edge_min.cover_max = 0.5;
  const RunSummary bounded = evaluate(scene, "edge-min", {}).summary;
  // Discs for boxes and a 32 x 18 grid for the metric's 80 x 44 pixels: 10 points of tolerance.
  EXPECT_LE(bounded.occlusion.central_max, 0.6);
  EXPECT_EQ(bounded.intersections.near_fragments, 0);
  EXPECT_EQ(bounded.intersections.camera_hit_fragments, 0);
}

}  // namespace
}  // namespace fragsim
