// The camera a person flies (play/flight_controls.cpp): held keys accelerate it at the declared
// bound up to V_c, and turn it at the turn rate.

#include "play/flight_controls.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "support/test_scenes.hpp"

namespace fragsim {
namespace {

using test::start_pose;

constexpr double kDt = 1.0 / 60.0;

TEST(FlightControls, AcceleratesAtTheBoundAndStopsAtVc) {
  CameraDef def;  // V_c 3 m/s, player_accel 20 m/s^2
  FlightControls c(def, start_pose());
  HeldControls held;
  held.forward = 1.0;
  // Speed after step n: min(20 n / 60, 3), so 3 m/s from step 9 on; the eye moves dt v per step:
  // after 9 steps z = -(1/60) (1 + ... + 9) / 3 = -0.25 m.
  CameraSample s;
  for (int n = 1; n <= 9; ++n) {
    s = c.step(held, n * kDt, kDt);
    EXPECT_NEAR(c.velocity_mps().norm(), std::min(n / 3.0, 3.0), 1e-12) << n;
  }
  EXPECT_NEAR(s.eye_m.z(), -0.25, 1e-12);
  EXPECT_NEAR(s.eye_m.x(), 0.0, 1e-15);
  held.right = 1.0;  // diagonal: no faster than V_c
  for (int n = 10; n <= 60; ++n) {
    c.step(held, n * kDt, kDt);
    EXPECT_LE(c.velocity_mps().norm(), 3.0) << n;
  }
  EXPECT_NEAR(c.velocity_mps().x(), 3.0 / std::sqrt(2.0), 1e-9);
}

TEST(FlightControls, KeysTurnAtTheTurnRate) {
  CameraDef def;  // 90 deg/s
  FlightControls c(def, start_pose());
  HeldControls held;
  held.yaw = 1.0;  // E: right
  CameraSample s;
  for (int n = 1; n <= 60; ++n) s = c.step(held, n * kDt, kDt);
  // A second at 90 deg/s: looking down +x, the right of -z; up stays world up.
  EXPECT_NEAR(s.forward.x(), 1.0, 1e-12);
  EXPECT_NEAR(s.forward.z(), 0.0, 1e-12);
  EXPECT_NEAR(s.up.y(), 1.0, 1e-12);
  held = {};
  held.mouse_pitch_rad = 0.5;  // consumed by one step
  s = c.step(held, 61 * kDt, kDt);
  EXPECT_EQ(held.mouse_pitch_rad, 0.0);
  EXPECT_NEAR(s.forward.y(), std::sin(0.5), 1e-12);
}

}  // namespace
}  // namespace fragsim
