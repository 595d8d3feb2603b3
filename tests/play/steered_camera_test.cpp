// The steered camera of a live flight (play/steered_camera.cpp): its samples, replayed as a
// track, answer a run's questions bit for bit.

#include "play/steered_camera.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "play/flight_controls.hpp"
#include "play/flight_record.hpp"
#include "sim/camera_track_file.hpp"
#include "sim/sampled_camera.hpp"
#include "support/test_scenes.hpp"

namespace fragsim {
namespace {

using test::start_pose;

constexpr double kDt = 1.0 / 60.0;

// A run asks a camera for step k's pose and velocity, then for k + 1's; the steered camera's
// samples replayed as a track must answer the same, bit for bit.
TEST(SteeredCamera, ReplaysBitForBitAsATrack) {
  CameraDef def;
  FlightControls c(def, start_pose());
  HeldControls held;
  SteeredCamera live(def, kDt, c.sample(0.0));
  const auto steer = [&] {
    const auto k = static_cast<int>(live.samples().size());
    held.forward = k < 40 ? 1.0 : -0.5;
    held.yaw = k > 20 ? 0.7 : 0.0;
    live.steer(c.step(held, live.next_t_s(), kDt));
  };
  std::vector<CameraPose> poses;
  std::vector<Eigen::Vector3d> velocities;
  for (int k = 0; k <= 80; ++k) {
    steer();  // the sample at (k + 1) dt: the velocity over step k needs it
    ASSERT_EQ(live.samples().size(), static_cast<std::size_t>(k + 2));
    EXPECT_EQ(live.samples()[k + 1].t_s, (k + 1) * kDt) << k;
    poses.push_back(live.pose_at(k * kDt));
    velocities.push_back(live.velocity_at(k * kDt));
  }
  const std::string csv = track_csv(def, "none", live.samples());
  const SampledCamera replay(def, parse_camera_track(csv, "flight.csv", "", def.max_speed_mps));
  for (int k = 0; k <= 80; ++k) {
    const CameraPose p = replay.pose_at(k * kDt);
    EXPECT_EQ(p.eye_m, poses[k].eye_m) << k;
    EXPECT_EQ(p.forward, poses[k].forward) << k;
    EXPECT_EQ(p.up, poses[k].up) << k;
    EXPECT_EQ(p.right, poses[k].right) << k;
    EXPECT_EQ(replay.velocity_at(k * kDt), velocities[k]) << k;
  }
}

}  // namespace
}  // namespace fragsim
