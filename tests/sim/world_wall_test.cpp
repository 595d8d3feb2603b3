// The wall strategy's kinematic wall in the world (src/sim/world.cpp): a fragment that begins the
// run inside the wall is let through until it is clear of it, and is an ordinary fragment after.

#include <gtest/gtest.h>

#include <vector>

#include "sim/camera_path.hpp"
#include "sim/world.hpp"
#include "support/test_scenes.hpp"

namespace fragsim {
namespace {

constexpr double kDt_s = 1.0 / 60.0;
constexpr double kHalf_m = 0.05;

// A still camera at (0, 1.6, 0) looking down -z; the wall 0.6 m ahead, 5 cm thick: z in
// [-0.625, -0.575]. Gravity (0, 0, +2 m/s^2) pulls toward the camera; the ground is far below.
Scene wall_scene() {
  Scene s = test::still_camera_scene("wall");
  s.sim.gravity_mps2 = {0.0, 0.0, 2.0};
  return s;
}

// A 10 cm cube of 0.5 kg, not spinning.
FragmentSpawn cube(const Eigen::Vector3d& position_m, const Eigen::Vector3d& velocity_mps) {
  FragmentSpawn s;
  s.position_m = position_m;
  s.velocity_mps = velocity_mps;
  s.angular_velocity_radps.setZero();
  s.half_extents_m = Eigen::Vector3d::Constant(kHalf_m);
  s.mass_kg = 0.5;
  return s;
}

WorldNeeds wall_needs() {
  WorldNeeds needs;
  needs.camera_wall = CameraWallSpec{0.6, 1.0, 1.0, 0.05, 0.3};
  return needs;
}

// A 10 cm cube centred in the wall, moving away from the camera at 1 m/s: z(t) = -0.6 - t + t^2.
// It overlaps the wall until its near face passes the wall's back face, z < -0.675 (t = 0.083 s),
// turns at t = 0.5 s (z = -0.85) and comes back to the wall at t = 0.92 s at 0.83 m/s.
TEST(WorldWall, FragmentBornInsideTheWallPassesOutThenBouncesLikeAnyOther) {
  const Scene scene = wall_scene();
  const CameraPath path(scene.camera);
  World world(scene, wall_needs(), {cube({0.0, 1.6, -0.6}, {0.0, 0.0, -1.0})});
  std::vector<FragmentState> state = world.init_states();
  int contacts = 0;
  double after_first_contact_mps = 0.0;
  for (int k = 0; k < 78; ++k) {  // to t = 1.3 s
    const double t = k * kDt_s;
    world.set_camera(path.pose_at(t), path.velocity_at(t));
    world.step(kDt_s);
    world.read(state);
    if (contacts == 0 && world.wall_contacts() > 0)
      after_first_contact_mps = state[0].velocity_mps.z();
    contacts += world.wall_contacts();
    if (k < 5) {
      // Let through: free flight exactly (semi-implicit Euler, v = -1 + 2 (k + 1) dt), no contact.
      EXPECT_EQ(world.wall_contacts(), 0);
      EXPECT_NEAR(state[0].velocity_mps.z(), -1.0 + 2.0 * (k + 1) * kDt_s, 1e-12);
      EXPECT_NEAR(state[0].velocity_mps.x(), 0.0, 1e-12);
      EXPECT_NEAR(state[0].velocity_mps.y(), 0.0, 1e-12);
    }
  }
  // Coming back from outside, it met the wall and bounced off it (restitution 0.3 of 0.83 m/s:
  // about -0.25 m/s); gravity has brought it back to rest on the wall's back face since, within
  // ODE's 1 mm surface layer.
  EXPECT_GT(contacts, 0);
  EXPECT_NEAR(after_first_contact_mps, -0.3 * 0.83, 0.05);
  EXPECT_NEAR(state[0].position_m.z(), -0.675, 0.002);
}

// The same cube outside the wall from the start, moving toward it: the wall stops it at once.
TEST(WorldWall, FragmentOutsideTheWallBouncesOffIt) {
  const Scene scene = wall_scene();
  const CameraPath path(scene.camera);
  // Its near face 2.5 cm short of the wall's back face.
  World world(scene, wall_needs(), {cube({0.0, 1.6, -0.7}, {0.0, 0.0, 3.0})});
  std::vector<FragmentState> state = world.init_states();
  int contacts = 0;
  for (int k = 0; k < 10; ++k) {
    const double t = k * kDt_s;
    world.set_camera(path.pose_at(t), path.velocity_at(t));
    world.step(kDt_s);
    contacts += world.wall_contacts();
  }
  world.read(state);
  EXPECT_GT(contacts, 0);
  EXPECT_LT(state[0].velocity_mps.z(), 0.0);  // going away from the camera again
  EXPECT_LT(state[0].position_m.z(), -0.675 + 0.01);
}

}  // namespace
}  // namespace fragsim
