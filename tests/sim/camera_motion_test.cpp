// Camera motions (camera.mode, sim/camera_motion.cpp): the limits a motion declares. The path,
// the replayed track and the seeded player are tested beside their own sources.

#include "sim/camera_motion.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "support/test_scenes.hpp"

namespace fragsim {
namespace {

using test::player_scene;

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(CameraMotion, DeclaredLimitsComeFromThePlayerOnly) {
  Scene s = player_scene();
  CameraLimits l = declared_limits(s.camera);
  EXPECT_EQ(l.max_speed_mps, 4.0);
  EXPECT_EQ(l.max_accel_mps2, 20.0);
  EXPECT_EQ(l.max_turn_degps, 90.0);
  s.camera.mode = CameraMode::kPath;
  l = declared_limits(s.camera);
  EXPECT_EQ(l.max_accel_mps2, kUndeclaredBound);  // not declared
  EXPECT_EQ(l.max_turn_degps, kUndeclaredBound);
  s.camera.mode = CameraMode::kPlayer;
  s.camera.player_accel_mps2 = kInf;  // declared: no bound
  EXPECT_EQ(declared_limits(s.camera).max_accel_mps2, kInf);
}

}  // namespace
}  // namespace fragsim
