// The sums over a 3-vector in their one order, (x + y) + z: a case whose two associations differ
// by a rounding, and a norm that is exact.
#include "control/geometry/vec3_sums.hpp"

#include <gtest/gtest.h>

namespace fragsim {
namespace {

TEST(Vec3Sums, DotAddsXAndYFirst) {
  // 1 + 1e-16 rounds to 1, so (x + y) + z is 0; but 1e-16 - 1 rounds to -1 + 2^-53, so
  // x + (y + z) is 2^-53 = 1.1e-16.
  const Eigen::Vector3d a(1.0, 1e-16, -1.0);
  const Eigen::Vector3d ones(1.0, 1.0, 1.0);
  EXPECT_EQ(dot3(a, ones), 0.0);
  EXPECT_EQ(a.x() + (a.y() + a.z()), 0x1p-53);
}

TEST(Vec3Sums, NormsOfAPythagoreanQuadruple) {
  const Eigen::Vector3d v(3.0, 4.0, 12.0);
  EXPECT_EQ(squared_norm3(v), 169.0);
  EXPECT_EQ(norm3(v), 13.0);
  EXPECT_EQ(dot3(v, Eigen::Vector3d(1.0, -1.0, 0.5)), 5.0);
}

}  // namespace
}  // namespace fragsim
