#include "control/geometry/parabola.hpp"

#include <gtest/gtest.h>

#include <random>

namespace fragsim {
namespace {

const Parabola kPath{{1.0, 2.0, 3.0}, {4.0, 5.0, 6.0}, {0.0, -10.0, 2.0}};

TEST(Parabola, AtHandValues) {
  EXPECT_EQ(kPath.at(0.0), kPath.p0_m);
  // p0 + 2 v0 + a * 4 / 2.
  EXPECT_EQ(kPath.at(2.0), Eigen::Vector3d(9.0, -8.0, 19.0));
  EXPECT_EQ(kPath.half_accel_mps2(), Eigen::Vector3d(0.0, -5.0, 1.0));
}

TEST(Parabola, RelativeForms) {
  const Parabola fixed = kPath.relative_to({1.0, 1.0, 1.0});
  EXPECT_EQ(fixed.at(2.0), Eigen::Vector3d(8.0, -9.0, 18.0));
  const Parabola moving = kPath.relative_to({1.0, 1.0, 1.0}, {1.0, 0.0, 0.0});
  EXPECT_EQ(moving.at(2.0), Eigen::Vector3d(6.0, -9.0, 18.0));  // the point moved 2 m along x
}

TEST(Parabola, AxisCoefficients) {
  const AxisQuadratic y = kPath.axis(1);
  EXPECT_EQ(y.c0, 2.0);
  EXPECT_EQ(y.c1, 5.0);
  EXPECT_EQ(y.c2, -5.0);
  EXPECT_EQ(y.at(2.0), -8.0);
  EXPECT_EQ(kPath.axis(2).at(2.0), 19.0);
}

// Halving is exact: a half-acceleration form built from the full one has the same bits, and
// doubling it back restores the parabola.
TEST(Parabola, HalfAccelerationFormIsBitIdentical) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-50.0, 50.0);
  for (int n = 0; n < 1000; ++n) {
    const Eigen::Vector3d half{u(rng), u(rng), u(rng)};
    const Parabola p{{u(rng), u(rng), u(rng)}, {u(rng), u(rng), u(rng)}, 2.0 * half};
    EXPECT_EQ(p.half_accel_mps2(), half);
    const double t = 0.01 * (u(rng) + 50.0);
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(p.axis(k).c2, half[k]);
      // at() is the expanded sum with the half acceleration.
      EXPECT_EQ(p.at(t)[k], p.p0_m[k] + p.v0_mps[k] * t + half[k] * t * t);
    }
  }
}

TEST(Parabola, InCameraFrame) {
  CameraPose cam;  // looking down -z
  cam.eye_m = {0.0, 0.0, 10.0};
  const Parabola path{{1.0, 2.0, 3.0}, {0.0, 0.0, -4.0}, {0.0, -10.0, 0.0}};
  const Parabola c = in_camera_frame(path, cam, {0.0, 0.0, -1.0});
  EXPECT_EQ(c.p0_m, Eigen::Vector3d(1.0, 2.0, 7.0));
  EXPECT_EQ(c.v0_mps, Eigen::Vector3d(0.0, 0.0, 3.0));
  EXPECT_EQ(c.accel_mps2, Eigen::Vector3d(0.0, -10.0, 0.0));
  // After 1 s: 3 m farther, 5 m lower.
  EXPECT_EQ(c.at(1.0), Eigen::Vector3d(1.0, -3.0, 10.0));
}

}  // namespace
}  // namespace fragsim
