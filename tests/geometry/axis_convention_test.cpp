// A file's frame into fragsim's (metres, Y up, right-handed): the four frames' maps as the header
// tables them, each a proper or mirrored rotation as its handedness says, and exact.

#include "geometry/axis_convention.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

namespace fragsim {
namespace {

const Eigen::Vector3d kP{1.0, 2.0, 3.0};

Eigen::Vector3d map(UpAxis up, Handedness h, const Eigen::Vector3d& v = kP) {
  return direction_to_fragsim({1.0, up, h}, v);
}

TEST(AxisConvention, TheFourFrames) {
  EXPECT_EQ(map(UpAxis::kY, Handedness::kRight), Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(map(UpAxis::kY, Handedness::kLeft), Eigen::Vector3d(1, 2, -3));   // Unity
  EXPECT_EQ(map(UpAxis::kZ, Handedness::kRight), Eigen::Vector3d(1, 3, -2));  // Blender
  EXPECT_EQ(map(UpAxis::kZ, Handedness::kLeft), Eigen::Vector3d(1, 3, 2));    // Unreal
  // The file's up is fragsim's up.
  EXPECT_EQ(map(UpAxis::kZ, Handedness::kRight, {0, 0, 1}), Eigen::Vector3d(0, 1, 0));
  EXPECT_EQ(map(UpAxis::kZ, Handedness::kLeft, {0, 0, 1}), Eigen::Vector3d(0, 1, 0));
}

TEST(AxisConvention, EachEnginesPointLandsTheSame) {
  // 1 m right, 2 m up, 3 m toward the viewer in fragsim's frame, as each tool writes it.
  const Eigen::Vector3d want(1, 2, 3);
  EXPECT_EQ(position_to_fragsim(AxisConvention{}, want), want);  // fragsim and glTF: as is
  // Unity: metres, Y up, left-handed, z away from the viewer.
  EXPECT_EQ(position_to_fragsim({1.0, UpAxis::kY, Handedness::kLeft}, {1, 2, -3}), want);
  // Blender: metres, Z up, right-handed, y away from the viewer (its glTF exporter's turn).
  EXPECT_EQ(position_to_fragsim({1.0, UpAxis::kZ, Handedness::kRight}, {1, -3, 2}), want);
  // Unreal: centimetres, Z up, left-handed: x forward, y right, z up. fragsim's x stays x and
  // its z (x cross y) is then Unreal's y.
  EXPECT_EQ(position_to_fragsim({0.01, UpAxis::kZ, Handedness::kLeft}, {100, 300, 200}), want);
}

TEST(AxisConvention, LeftHandedFramesAreMirrored) {
  // x cross y is z in a right-handed file; a left-handed file's x cross y maps to -z's image.
  for (const UpAxis up : {UpAxis::kY, UpAxis::kZ}) {
    for (const Handedness h : {Handedness::kRight, Handedness::kLeft}) {
      const Eigen::Vector3d x = map(up, h, {1, 0, 0});
      const Eigen::Vector3d y = map(up, h, {0, 1, 0});
      const Eigen::Vector3d z = map(up, h, {0, 0, 1});
      EXPECT_EQ(x.cross(y), h == Handedness::kRight ? z : Eigen::Vector3d(-z));
    }
  }
}

TEST(AxisConvention, UnitScalesPositionsOnlyAndNoNegativeZeroAppears) {
  const AxisConvention unreal{0.01, UpAxis::kZ, Handedness::kLeft};
  EXPECT_EQ(position_to_fragsim(unreal, {150, 1025, 160}), Eigen::Vector3d(1.5, 1.6, 10.25));
  EXPECT_EQ(direction_to_fragsim(unreal, {0, 1, 0}), Eigen::Vector3d(0, 0, 1));
  const AxisConvention blender{1.0, UpAxis::kZ, Handedness::kRight};
  const Eigen::Vector3d p = position_to_fragsim(blender, {1, 0, 2});
  EXPECT_FALSE(std::signbit(p.z())) << "a file's 0 is fragsim's +0";
  EXPECT_TRUE(AxisConvention{}.is_identity());
  EXPECT_FALSE(blender.is_identity());
}

}  // namespace
}  // namespace fragsim
