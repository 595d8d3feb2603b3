// The change of frame behind fragsim_step_input.ground_normal (api/ground_frame.cpp): a normal
// along an axis is a signed permutation that rounds nothing; any other normal a rotation that takes
// it to +y. Worked by hand: z-up's (x, y, z) is y-up's (x, z, -y).

#include "control/api/ground_frame.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <vector>

namespace {

using fragsim::control::GroundFrame;

// A few ulp at 1: the rows of a rotation built from a unit normal (Duff et al.'s construction is
// accurate to a few ulp).
constexpr double kTol = 1e-15;

TEST(GroundFrame, ZUpIsTheSwapOfYAndZWithZNegated) {
  const GroundFrame f(fragsim_vec3{0.0, 0.0, 1.0});
  EXPECT_TRUE(f.permutation());
  EXPECT_EQ(f.in({1.0, 2.0, 3.0}), Eigen::Vector3d(1.0, 3.0, -2.0));
  EXPECT_EQ(f.out({1.0, 3.0, -2.0}), Eigen::Vector3d(1.0, 2.0, 3.0));
  // A point 1.5 m above a z-up ground at height 0 is 1.5 m above the y-up ground.
  EXPECT_EQ(f.in({0.25, -4.0, 1.5}).y(), 1.5);
}

TEST(GroundFrame, EveryAxisGoesToPlusYByAProperRotationExactly) {
  const std::vector<fragsim_vec3> axes = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                          {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
  for (const fragsim_vec3& n : axes) {
    const GroundFrame f(n);
    EXPECT_TRUE(f.permutation());
    const Eigen::Vector3d up = f.in({n.x, n.y, n.z});
    EXPECT_EQ(up, Eigen::Vector3d(0.0, 1.0, 0.0)) << n.x << " " << n.y << " " << n.z;
    // Right-handed: the images of x and y cross to the image of z, exactly (entries 0 and +-1).
    const Eigen::Vector3d x = f.in(Eigen::Vector3d::UnitX());
    const Eigen::Vector3d y = f.in(Eigen::Vector3d::UnitY());
    EXPECT_EQ(x.cross(y), f.in(Eigen::Vector3d::UnitZ())) << n.x << " " << n.y << " " << n.z;
    const Eigen::Vector3d w(0.5, -7.25, 3.0);
    EXPECT_EQ(f.out(f.in(w)), w);
  }
}

TEST(GroundFrame, TiltedNormalGoesToPlusYAndTheFrameStaysOrthonormal) {
  // Not unit on purpose (the frame normalises), and one near -z, where the classic construction
  // cancels.
  for (const Eigen::Vector3d& given :
       {Eigen::Vector3d(3.0, 4.0, 0.0), Eigen::Vector3d(0.2, 1.0, -0.3),
        Eigen::Vector3d(1e-3, 2e-3, -1.0)}) {
    const GroundFrame f(fragsim_vec3{given.x(), given.y(), given.z()});
    EXPECT_FALSE(f.permutation());
    const Eigen::Vector3d n = given.normalized();
    EXPECT_NEAR((f.in(n)-Eigen::Vector3d(0.0, 1.0, 0.0)).norm(), 0.0, kTol) << given.transpose();
    const Eigen::Vector3d x = f.in(Eigen::Vector3d::UnitX());
    const Eigen::Vector3d y = f.in(Eigen::Vector3d::UnitY());
    const Eigen::Vector3d z = f.in(Eigen::Vector3d::UnitZ());
    EXPECT_NEAR(x.norm(), 1.0, kTol);
    EXPECT_NEAR(y.norm(), 1.0, kTol);
    EXPECT_NEAR(x.dot(y), 0.0, kTol);
    EXPECT_NEAR((x.cross(y) - z).norm(), 0.0, kTol);  // a rotation, not a reflection
    // The plane dot(n, p) = 2 becomes y = 2: a point on it, 2 n plus a step along the plane.
    const Eigen::Vector3d along = n.cross(Eigen::Vector3d::UnitX()).normalized();
    EXPECT_NEAR(f.in(2.0 * n + 5.0 * along).y(), 2.0, 10 * kTol);
    const Eigen::Vector3d w(0.5, -7.25, 3.0);
    EXPECT_NEAR((f.out(f.in(w)) - w).norm(), 0.0, 10 * kTol);
  }
}

}  // namespace
