// The `fade` strategy: its opacity ramp worked by hand, the distance to a box's nearest point,
// the next frame's prediction and its keys' rules.

#include "strategies/fade_strategy.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "sim/scene_strategies.hpp"

namespace fragsim {
namespace {

FragmentState box_at(const Eigen::Vector3d& p, double half_m = 0.05) {
  FragmentState f;
  f.position_m = p;
  f.half_extents_m = Eigen::Vector3d::Constant(half_m);
  f.radius_m = half_m * std::sqrt(3.0);
  f.mass_kg = 1.0;
  return f;
}

// The defaults: opaque from 1 m out, invisible from 0.25 m in.
TEST(FadeOpacity, OneAtStartZeroAtEndLinearBetween) {
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

TEST(FadeDistance, NearestPointOfTheBox) {
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
  StepOutput out;
  fade.step(ctx, out);
  EXPECT_TRUE(out.forces.empty());
  ASSERT_EQ(out.opacity.size(), 2u);
  // Next frame: the near face at -0.95, the eye at -0.1: 0.85 m, opacity (0.85 - 0.25) / 0.75.
  EXPECT_NEAR(out.opacity[0], 0.8, 1e-6);
  EXPECT_EQ(out.opacity[1], 1.0f);
}

TEST(FadeParams, EndMustBeNearerThanStartAndEachKeyInRange) {
  Scene scene;
  const auto error = [&scene]() -> std::string {
    try {
      make_strategy("fade", scene);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_EQ(error(), "");
  scene.get<FadeParams>().end_m = 1.0;  // equal to start_m: no ramp
  EXPECT_NE(error().find("fade.end_m = 1: must be < fade.start_m = 1"), std::string::npos)
      << error();
  scene.get<FadeParams>().end_m = 2.0;
  EXPECT_NE(error().find("fade.end_m"), std::string::npos) << error();
  scene.get<FadeParams>().end_m = -0.1;
  EXPECT_NE(error().find("fade.end_m"), std::string::npos) << error();
  scene.get<FadeParams>().end_m = 0.0;  // invisible only at the eye: allowed
  EXPECT_EQ(error(), "");
  scene.get<FadeParams>().start_m = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(error().find("fade.start_m"), std::string::npos) << error();
  scene.get<FadeParams>().start_m = 0.0;
  EXPECT_NE(error().find("fade.start_m"), std::string::npos) << error();
}

}  // namespace
}  // namespace fragsim
