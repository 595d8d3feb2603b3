// The camera on a path of waypoints (sim/camera_path.cpp): one look-at point per waypoint pans,
// one look-at point keeps its meaning.

#include "sim/camera_path.hpp"

#include <gtest/gtest.h>

#include "support/test_scenes.hpp"

namespace fragsim {
namespace {

using test::three_point_path;

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

}  // namespace
}  // namespace fragsim
