// The `fade` strategy: its opacity ramp worked by hand, the distance to a box's nearest point,
// the next frame's prediction, and whole runs of one fragment fired at the lens and one passing
// beside it (hand-placed scenes of support/test_scenes.hpp). Its keys' rules are in
// fade_params_test.cpp.

#include "strategies/fade_strategy.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "experiments/evaluation.hpp"
#include "sim/scene_strategies.hpp"
#include "support/test_scenes.hpp"

namespace fragsim {
namespace {

FragmentState box_at(const Eigen::Vector3d& p, double half_m = 0.05) {
  return test::box_at(p, half_m);
}

// The defaults: opaque from 1 m out, invisible from 0.25 m in.
TEST(FadeStrategy, OneAtStartZeroAtEndLinearBetween) {
  const FadeParams p;
  ASSERT_EQ(p.start_m, 1.0);
  ASSERT_EQ(p.end_m, 0.25);
  // float results of double arithmetic: 1e-7 is a few float ulps at 1.
  constexpr double kTol = 1e-7;
  EXPECT_NEAR(fade_opacity(p, 1.0), 1.0, kTol);
  EXPECT_NEAR(fade_opacity(p, 0.25), 0.0, kTol);
  EXPECT_NEAR(fade_opacity(p, 0.625), 0.5, kTol);    // half way
  EXPECT_NEAR(fade_opacity(p, 0.4375), 0.25, kTol);  // a quarter of the way from end_m
  EXPECT_NEAR(fade_opacity(p, 0.8125), 0.75, kTol);
  EXPECT_EQ(fade_opacity(p, 5.0), 1.0f);  // clamped beyond start_m
  EXPECT_EQ(fade_opacity(p, 0.1), 0.0f);  // and inside end_m
  EXPECT_EQ(fade_opacity(p, 0.0), 0.0f);
  EXPECT_EQ(fade_opacity(p, std::numeric_limits<double>::quiet_NaN()), 0.0f);
  // Linear: equal steps in distance give equal steps in opacity.
  for (double d = 0.25; d <= 1.0; d += 0.05) {
    EXPECT_NEAR(fade_opacity(p, d), (d - 0.25) / 0.75, kTol) << d;
  }
}

TEST(FadeStrategy, NearestPointOfTheBox) {
  const Eigen::Vector3d eye(0.0, 0.0, 0.0);
  // Face on: the near face is 1 - 0.05 away.
  EXPECT_NEAR(box_distance_m(eye, box_at({0.0, 0.0, -1.0})), 0.95, 1e-15);
  // Off to the side and ahead: to the nearest corner (0.95, 0.45, 0.95 away on each axis).
  EXPECT_NEAR(box_distance_m(eye, box_at({1.0, 0.5, -1.0})), std::sqrt(2 * 0.95 * 0.95 + 0.2025),
              1e-15);
  // Turned 45 degrees about y, the box shows an edge to the eye: 1 - 0.05 sqrt(2).
  FragmentState turned = box_at({0.0, 0.0, -1.0});
  turned.rotation = Eigen::AngleAxisd(0.25 * kPi, Eigen::Vector3d::UnitY()).toRotationMatrix();
  EXPECT_NEAR(box_distance_m(eye, turned), 1.0 - 0.05 * std::sqrt(2.0), 1e-15);
  // The eye inside the box: 0.
  EXPECT_EQ(box_distance_m(eye, box_at({0.01, -0.02, 0.03})), 0.0);
}

// The opacity is for the frame after the step: fragment and eye moved on by one step.
TEST(FadeStrategy, AnswersTheNextFramesOpacityAndNoForce) {
  FadeStrategy fade{FadeParams{}};
  fade.reset(2);
  std::vector<FragmentState> frags{box_at({0.0, 1.6, -1.5}), box_at({0.0, 1.6, -20.0})};
  frags[0].velocity_mps = {0.0, 0.0, 30.0};  // 0.5 m in a 1/60 s step: centre at -1.0 next
  StepContext ctx;
  ctx.dt_s = 1.0 / 60.0;
  ctx.camera.eye_m = {0.0, 1.6, 0.0};
  ctx.camera_velocity_mps = {0.0, 0.0, -6.0};  // the eye moves 0.1 m toward it: eye at -0.1
  ctx.fragments = frags;
  SceneStepOutput out;
  fade.step(ctx, out);
  EXPECT_TRUE(out.forces.empty());
  ASSERT_EQ(out.opacity.size(), 2u);
  // Next frame: the near face at -0.95, the eye at -0.1: 0.85 m, opacity (0.85 - 0.25) / 0.75.
  EXPECT_NEAR(out.opacity[0], 0.8, 1e-6);
  EXPECT_EQ(out.opacity[1], 1.0f);
}

// Each snapshot's opacities.
class OpacityRecorder final : public RunObserver {
 public:
  std::vector<std::vector<float>> steps;
  void begin(const RunInfo&, const StepSnapshot& s) override { keep(s); }
  void observe(const StepSnapshot& s) override { keep(s); }

 private:
  void keep(const StepSnapshot& s) { steps.emplace_back(s.opacity.begin(), s.opacity.end()); }
};

// 10 m/s straight at the lens from 5 m: without control it meets the near rectangle; faded, it is
// invisible from 0.25 m (three frames of 0.167 m before the near plane), so it is never drawn
// cut, and it vanishes: it dropped below half opacity at 0.625 m, in the middle of the view.
TEST(FadeStrategy, FragmentFiredAtTheLensIsNoIntersectionButVanishes) {
  const Scene scene = test::single_fragment({0.0, 1.6, -5.0}, 10.0);
  const RunSummary none = evaluate(scene, "none").summary;
  ASSERT_EQ(none.intersections.near_fragments, 1);
  EXPECT_EQ(none.intersections.vanished_fragments, 0);
  OpacityRecorder rec;
  EvaluationOptions opts;
  opts.extra = {&rec};
  const RunSummary fade = evaluate(scene, "fade", opts).summary;
  EXPECT_EQ(fade.intersections.near_fragments, 0);
  EXPECT_EQ(fade.intersections.near_fragment_steps, 0);
  EXPECT_EQ(fade.intersections.vanished_fragments, 1);
  // Physics untouched: what the body meets is the same, and no force was applied.
  EXPECT_EQ(fade.intersections.camera_hit_fragments, none.intersections.camera_hit_fragments);
  EXPECT_EQ(fade.activity.impulse_Ns, 0.0);
  EXPECT_EQ(fade.activity.forced_fragments, 0);
  // Step 0 is drawn before the strategy speaks (opaque); every later frame has an opacity.
  ASSERT_EQ(rec.steps.size(), static_cast<std::size_t>(scene.step_count()) + 1);
  EXPECT_TRUE(rec.steps[0].empty());
  // 0.1 s in, the near face is 5 - 0.05 - 1 = 3.95 m away: opaque.
  ASSERT_EQ(rec.steps[6].size(), 1u);
  EXPECT_EQ(rec.steps[6][0], 1.0f);
  // Step 27 (0.45 s): the near face 5 - 0.05 - 4.5 = 0.45 m away: opacity (0.45 - 0.25) / 0.75.
  EXPECT_NEAR(rec.steps[27][0], 0.2 / 0.75, 1e-6);
  // Step 29: the near face 0.117 m away, inside end_m; step 30 (0.5 s): the eye is inside the
  // box. The sweep from 29 to 30 meets the near rectangle, invisible at both ends.
  EXPECT_EQ(rec.steps[29][0], 0.0f);
  EXPECT_EQ(rec.steps[30][0], 0.0f);
}

// Beside the camera: 0.6 m to the right at eye height, flying past. Its box comes within 0.55 m
// of the eye, so it does fade below half (opacity 0.4 at its closest), but only once its near
// face is less than sqrt(0.625^2 - 0.55^2) = 0.297 m ahead of the eye: first at step 28, centre
// 0.333 m ahead, where the frustum's half width is 0.342 m and the box's bounding sphere
// (0.087 m) lies 0.18 m outside the side plane. It left the picture through its edge before it
// faded: not vanished.
TEST(FadeStrategy, FragmentThatFadesOutsideTheViewHasNotVanished) {
  const Scene scene = test::single_fragment({0.6, 1.6, -5.0}, 10.0);
  OpacityRecorder rec;
  EvaluationOptions opts;
  opts.extra = {&rec};
  const RunSummary fade = evaluate(scene, "fade", opts).summary;
  float lowest = 1.0f;
  for (const auto& step : rec.steps) {
    if (!step.empty()) lowest = std::min(lowest, step[0]);
  }
  EXPECT_NEAR(lowest, (0.55 - 0.25) / 0.75, 0.01);  // it did fade below half
  EXPECT_EQ(fade.intersections.vanished_fragments, 0);
  EXPECT_EQ(fade.intersections.near_fragments, 0);
}

// Far from any fragment the fade changes nothing: every number of `none` but the strategy's name.
TEST(FadeStrategy, DistantFragmentRunsAsNone) {
  const Scene scene = test::single_fragment({3.0, 1.6, -5.0}, 10.0);
  RunSummary none = evaluate(scene, "none").summary;
  RunSummary fade = evaluate(scene, "fade").summary;
  none.strategy = fade.strategy;
  none.cost.physics_ms_median = fade.cost.physics_ms_median = 0.0;
  none.cost.physics_ms_p95 = fade.cost.physics_ms_p95 = 0.0;
  none.cost.strategy_ms_median = fade.cost.strategy_ms_median = 0.0;
  none.cost.strategy_ms_p95 = fade.cost.strategy_ms_p95 = 0.0;
  none.cost.wall_s = fade.cost.wall_s = 0.0;
  EXPECT_EQ(summary_fields(fade), summary_fields(none));
}

}  // namespace
}  // namespace fragsim
