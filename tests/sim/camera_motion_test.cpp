// Camera motions (camera.mode): a path that pans, a replayed track and the seeded player.

#include "sim/camera_motion.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "sim/camera_path.hpp"
#include "sim/player_camera.hpp"
#include "sim/sampled_camera.hpp"

namespace fragsim {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

CameraDef three_point_path() {
  CameraDef c;
  c.waypoints_m = {{0.0, 1.6, 0.0}, {0.0, 1.6, -2.0}, {1.5, 1.6, -4.0}};
  c.look_at_m = {{0.0, 1.2, -10.0}};
  c.speed_mps = 2.0;
  c.max_speed_mps = 3.0;
  return c;
}

std::vector<CameraSample> sample(const CameraMotion& m, double dt, int count) {
  std::vector<CameraSample> out;
  for (int k = 0; k < count; ++k) {
    const CameraPose p = m.pose_at(k * dt);
    out.push_back({k * dt, p.eye_m, p.forward, p.up});
  }
  return out;
}

TEST(CameraPath, OneLookAtPointPerWaypointPans) {
  CameraDef c = three_point_path();
  c.look_at_m = {{0.0, 1.6, -10.0}, {10.0, 1.6, -2.0}, {10.0, 1.6, 6.0}};
  const CameraPath path(c);
  // Halfway along the first 2 m segment (t = 0.5 s at 2 m/s) the target is halfway between the
  // first two look-at points: (5, 1.6, -6), seen from (0, 1.6, -1).
  const CameraPose p = path.pose_at(0.5);
  EXPECT_NEAR((p.eye_m - Eigen::Vector3d(0.0, 1.6, -1.0)).norm(), 0.0, 1e-12);
  const Eigen::Vector3d expected = Eigen::Vector3d(5.0, 0.0, -5.0).normalized();
  EXPECT_NEAR((p.forward - expected).norm(), 0.0, 1e-12);
  // After the end the last point is looked at.
  EXPECT_NEAR((path.look_at(100.0) - Eigen::Vector3d(10.0, 1.6, 6.0)).norm(), 0.0, 0.0);
}

TEST(CameraPath, OneLookAtPointKeepsItsMeaning) {
  const CameraDef c = three_point_path();
  const CameraPath path(c);
  for (double t : {0.0, 0.4, 1.3, 2.0, 9.0}) {
    const CameraPose p = path.pose_at(t);
    EXPECT_NEAR((p.forward - (c.look_at_m.front() - p.eye_m).normalized()).norm(), 0.0, 1e-15);
  }
}

// A track sampled from a known path at the physics step reproduces it: exactly at the samples,
// and to 1e-12 m between samples that lie on one segment.
TEST(SampledCamera, TrackSampledFromAPathReproducesIt) {
  const CameraDef c = three_point_path();
  const CameraPath path(c);
  const double dt = 1.0 / 60.0;
  const SampledCamera track(c, sample(path, dt, 300));
  double worst_m = 0.0;
  for (int k = 0; k < 299; ++k) {
    EXPECT_EQ(track.eye_at(k * dt), path.eye_at(k * dt));
    EXPECT_EQ(track.pose_at(k * dt).forward, path.pose_at(k * dt).forward);
    // Between samples, where no corner of the path lies between them (corners at 1 s and 2.25 s).
    const double t = (k + 0.37) * dt;
    const bool straddles =
        (k * dt < 1.0 && (k + 1) * dt > 1.0) || (k * dt < 2.25 && (k + 1) * dt > 2.25);
    if (!straddles) worst_m = std::max(worst_m, (track.eye_at(t) - path.eye_at(t)).norm());
  }
  EXPECT_LT(worst_m, 1e-12);
  // The velocity over a sample interval is that interval's: 2 m/s along the first segment.
  EXPECT_NEAR((track.velocity_at(0.2) - Eigen::Vector3d(0.0, 0.0, -2.0)).norm(), 0.0, 1e-12);
}

TEST(SampledCamera, HoldsTheEndPosesOutsideTheSamples) {
  CameraDef c;
  const std::vector<CameraSample> s{{1.0, {0, 1, 0}, {0, 0, -1}, {0, 1, 0}},
                                    {2.0, {1, 1, 0}, {1, 0, 0}, {0, 1, 0}}};
  const SampledCamera track(c, s);
  // Before the first sample: the first pose, standing still.
  EXPECT_EQ(track.eye_at(0.0), s[0].eye_m);
  EXPECT_EQ(track.pose_at(-5.0).forward, s[0].forward);
  EXPECT_EQ(track.velocity_at(0.5), Eigen::Vector3d::Zero());
  // Inside: the interval's velocity, 1 m/s along x.
  EXPECT_EQ(track.velocity_at(1.0), Eigen::Vector3d(1, 0, 0));
  // At and after the last sample: the last pose, standing still.
  EXPECT_EQ(track.eye_at(7.0), s[1].eye_m);
  EXPECT_EQ(track.pose_at(2.0).forward, s[1].forward);
  EXPECT_EQ(track.velocity_at(2.0), Eigen::Vector3d::Zero());
}

// Half way between a view down -z and one turned 90 degrees to +x, slerp looks 45 degrees
// between them, with the same up.
TEST(SampledCamera, SlerpMidpointOfTwoPoses) {
  CameraDef c;
  const std::vector<CameraSample> s{{0.0, {0, 0, 0}, {0, 0, -1}, {0, 1, 0}},
                                    {1.0, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}}};
  const SampledCamera track(c, s);
  const CameraPose mid = track.pose_at(0.5);
  const double h = std::sqrt(0.5);
  EXPECT_NEAR((mid.forward - Eigen::Vector3d(h, 0, -h)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((mid.up - Eigen::Vector3d(0, 1, 0)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((mid.right - Eigen::Vector3d(h, 0, h)).norm(), 0.0, 1e-12);
  // A quarter of the way: 22.5 degrees.
  const CameraPose q = track.pose_at(0.25);
  const double a = 22.5 * kPi / 180.0;
  EXPECT_NEAR((q.forward - Eigen::Vector3d(std::sin(a), 0, -std::cos(a))).norm(), 0.0, 1e-12);
}

Scene player_scene() {
  Scene s;
  s.camera.mode = CameraMode::kPlayer;
  s.camera.waypoints_m = {{0.0, 1.6, 0.0}};
  s.camera.look_at_m = {{0.0, 1.2, -10.0}};
  s.camera.max_speed_mps = 4.0;
  s.object.centre_m = {0.0, 1.2, -10.0};
  return s;
}

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
