// The seeded player (sim/player_camera.cpp): a straight line for an infinite interval, its start,
// its seed, and its speed, acceleration and turn bounds.

#include "sim/player_camera.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "support/test_scenes.hpp"

namespace fragsim {
namespace {

using test::player_scene;

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(PlayerCamera, InfiniteIntervalIsAStraightLine) {
  Scene s = player_scene();
  s.camera.player_interval_s = kInf;
  const std::vector<CameraSample> track = player_track(s);
  ASSERT_GT(track.size(), 100u);
  const double dt = s.sim.dt_s;
  const Eigen::Vector3d v = (track[1].eye_m - track[0].eye_m) / dt;
  EXPECT_GT(v.norm(), 0.0);
  EXPECT_LE(v.norm(), 4.0 + 1e-12);
  EXPECT_EQ(v.y(), 0.0);  // a walking player keeps its height
  for (std::size_t k = 0; k < track.size(); ++k) {
    const Eigen::Vector3d expected = track[0].eye_m + static_cast<double>(k) * dt * v;
    EXPECT_NEAR((track[k].eye_m - expected).norm(), 0.0, 1e-12) << "sample " << k;
  }
}

TEST(PlayerCamera, StartsAtTheFirstWaypointLookingAtTheTarget) {
  const Scene s = player_scene();
  const std::vector<CameraSample> track = player_track(s);
  EXPECT_EQ(track[0].eye_m, s.camera.waypoints_m.front());
  const Eigen::Vector3d f = (s.camera.look_at_m.front() - track[0].eye_m).normalized();
  EXPECT_NEAR((track[0].forward - f).norm(), 0.0, 1e-15);
}

TEST(PlayerCamera, SameSeedSameTrackOtherSeedOtherTrack) {
  Scene s = player_scene();
  const std::vector<CameraSample> a = player_track(s);
  const std::vector<CameraSample> b = player_track(s);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].eye_m, b[k].eye_m);
    EXPECT_EQ(a[k].forward, b[k].forward);
  }
  s.sim.seed = 2;
  const std::vector<CameraSample> c = player_track(s);
  EXPECT_GT((c.back().eye_m - a.back().eye_m).norm(), 0.1);
}

// Speed at most V_c, velocity changes at most A dt per step, turns at most w dt per step; the
// defaults make a player that changes its mind several times in a run and reverses.
TEST(PlayerCamera, HonoursItsBounds) {
  Scene s = player_scene();
  s.sim.duration_s = 20.0;
  const std::vector<CameraSample> track = player_track(s);
  const double dt = s.sim.dt_s;
  const double accel = s.camera.player_accel_mps2;
  const double turn_rad = s.camera.turn_rate_degps * kPi / 180.0 * dt;
  int reversals = 0;
  for (std::size_t k = 0; k + 2 < track.size(); ++k) {
    const Eigen::Vector3d v0 = (track[k + 1].eye_m - track[k].eye_m) / dt;
    const Eigen::Vector3d v1 = (track[k + 2].eye_m - track[k + 1].eye_m) / dt;
    EXPECT_LE(v0.norm(), 4.0 * (1 + 1e-12));
    EXPECT_LE((v1 - v0).norm(), accel * dt * (1 + 1e-9)) << "step " << k;
    const double angle =
        std::acos(std::clamp(track[k].forward.dot(track[k + 1].forward), -1.0, 1.0));
    EXPECT_LE(angle, turn_rad + 1e-9);
    if (k % 30 == 0 && k + 31 < track.size()) {
      const Eigen::Vector3d later = (track[k + 31].eye_m - track[k + 30].eye_m) / dt;
      if (v0.norm() > 1.0 && later.norm() > 1.0 && v0.dot(later) < -0.5 * v0.norm() * later.norm())
        ++reversals;
    }
  }
  EXPECT_GT(reversals, 3);
}

TEST(PlayerCamera, InstantTurnsChangeVelocityInOneStep) {
  Scene s = player_scene();
  s.camera.player_accel_mps2 = kInf;
  s.sim.duration_s = 20.0;
  const std::vector<CameraSample> track = player_track(s);
  const double dt = s.sim.dt_s;
  double largest_change = 0.0;
  for (std::size_t k = 0; k + 2 < track.size(); ++k) {
    const Eigen::Vector3d v0 = (track[k + 1].eye_m - track[k].eye_m) / dt;
    const Eigen::Vector3d v1 = (track[k + 2].eye_m - track[k + 1].eye_m) / dt;
    EXPECT_LE(v0.norm(), 4.0 * (1 + 1e-12));
    largest_change = std::max(largest_change, (v1 - v0).norm());
  }
  // A reversal at full speed is a change of 2 V_c = 8 m/s within one step.
  EXPECT_GT(largest_change, 4.0);
}

}  // namespace
}  // namespace fragsim
