// A replayed camera track (sim/sampled_camera.cpp): a track sampled from a known path reproduces
// it, the end poses hold outside the samples, and orientations are slerped between them.

#include "sim/sampled_camera.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "sim/camera_path.hpp"
#include "support/test_scenes.hpp"

namespace fragsim {
namespace {

using test::three_point_path;

std::vector<CameraSample> sample(const CameraMotion& m, double dt, int count) {
  std::vector<CameraSample> out;
  for (int k = 0; k < count; ++k) {
    const CameraPose p = m.pose_at(k * dt);
    out.push_back({k * dt, p.eye_m, p.forward, p.up});
  }
  return out;
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

}  // namespace
}  // namespace fragsim
