#include "geometry/camera_box.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <limits>

namespace fragsim {
namespace {

FragmentState box_at(const Eigen::Vector3d& centre_m, const Eigen::Matrix3d& rotation) {
  FragmentState f;
  f.position_m = centre_m;
  f.rotation = rotation;
  f.half_extents_m = {0.125, 0.25, 0.5};  // exact in binary, so the corners are exact
  return f;
}

// The default camera looks down -z: world x, y, -z are camera x, y, z (depth).
TEST(CameraBox, CornersOfAnAxisAlignedBox) {
  CameraPose cam;
  cam.eye_m = {1.0, 2.0, 3.0};
  const CameraBox b = camera_box(cam, box_at({1.0, 2.0, -2.0}, Eigen::Matrix3d::Identity()));
  EXPECT_EQ(b.centre_m, Eigen::Vector3d(0.0, 0.0, 5.0));
  ASSERT_TRUE(b.finite());
  const auto c = b.corners();
  EXPECT_EQ(c[0], Eigen::Vector3d(-0.125, -0.25, 5.5));  // body -z is camera +z
  EXPECT_EQ(c[7], Eigen::Vector3d(0.125, 0.25, 4.5));
  EXPECT_EQ(c[5], Eigen::Vector3d(0.125, -0.25, 4.5));  // bits 0 and 2
  EXPECT_EQ(c[2], Eigen::Vector3d(-0.125, 0.25, 5.5));
  for (int i = 0; i < 8; ++i) EXPECT_EQ(c[static_cast<std::size_t>(i)], b.corner(i));
  EXPECT_EQ(camera_aligned_extents(cam, box_at({1.0, 2.0, -2.0}, Eigen::Matrix3d::Identity())),
            Eigen::Vector3d(0.125, 0.25, 0.5));
}

// A camera looking along +x: right is +z, up is +y.
TEST(CameraBox, CornersSeenFromATurnedCamera) {
  CameraPose cam;
  cam.forward = {1.0, 0.0, 0.0};
  cam.right = {0.0, 0.0, 1.0};
  cam.up = {0.0, 1.0, 0.0};
  const FragmentState f = box_at({5.0, 0.0, 0.0}, Eigen::Matrix3d::Identity());
  const CameraBox b = camera_box(cam, f);
  EXPECT_EQ(b.centre_m, Eigen::Vector3d(0.0, 0.0, 5.0));
  // Corner 1: body +x (depth + 0.125), body -y, body -z (world -z is camera -x).
  EXPECT_EQ(b.corner(1), Eigen::Vector3d(-0.5, -0.25, 5.125));
  EXPECT_EQ(camera_aligned_extents(cam, f), Eigen::Vector3d(0.5, 0.25, 0.125));
}

TEST(CameraBox, ExtentsOfARotatedBox) {
  CameraPose cam;
  // A quarter turn about y swaps the box's x and z extents.
  const Eigen::Matrix3d quarter = Eigen::AngleAxisd(0.5 * kPi, Eigen::Vector3d::UnitY()).matrix();
  const Eigen::Vector3d e = camera_aligned_extents(cam, box_at({0.0, 0.0, -4.0}, quarter));
  EXPECT_NEAR(e.x(), 0.5, 1e-15);
  EXPECT_NEAR(e.y(), 0.25, 1e-15);
  EXPECT_NEAR(e.z(), 0.125, 1e-15);
}

TEST(CameraBox, NonFiniteStateIsFlagged) {
  FragmentState f = box_at({0.0, 0.0, -4.0}, Eigen::Matrix3d::Identity());
  f.position_m.x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(camera_box(CameraPose{}, f).finite());
}

}  // namespace
}  // namespace fragsim
