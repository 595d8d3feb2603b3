// The box test of the cheap rejection (box_clearance.hpp) must be conservative: whatever it calls
// clear, the exact answer calls clear too. Hand-checkable cases with worked-out distances, then
// random paths (fixed seeds) built to graze the box's faces. And the batched test must answer
// exactly as the single one.

#include "control/strategies/box_clearance.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "support/random_paths.hpp"

namespace fragsim {
namespace {

using test::enters_box;
using test::random_box_path;
using test::random_unit;

const Eigen::Vector3d kG(0.0, -9.81, 0.0);

// The path relative to the region's centre.
Parabola line(const Eigen::Vector3d& d, const Eigen::Vector3d& v,
              const Eigen::Vector3d& g = Eigen::Vector3d::Zero()) {
  return {d, v, g};
}

const Eigen::Vector3d kLo(-0.3, -0.25, -0.2);
const Eigen::Vector3d kHi(0.3, 0.25, 0.25);

TEST(BoxClearance, FiredStraightAtTheBoxIsNeverCleared) {
  for (const Eigen::Vector3d& g : {Eigen::Vector3d(Eigen::Vector3d::Zero()), kG}) {
    // Aimed so that gravity is compensated: at the centre at tau = 1 s.
    const Parabola p = line({0.0, 0.0, 10.0}, Eigen::Vector3d(0.0, 0.0, -10.0) - 0.5 * g, g);
    EXPECT_FALSE(path_clears_box(p, kLo, kHi, 3.0));
    EXPECT_TRUE(enters_box(p, kLo, kHi, 3.0));
  }
}

TEST(BoxClearance, PassingBesideByAKnownDistance) {
  // Along z at x = 0.31, 1 cm beyond the x face: cleared; at x = 0.29: enters.
  EXPECT_TRUE(path_clears_box(line({0.31, 0.0, 10.0}, {0.0, 0.0, -10.0}), kLo, kHi, 3.0));
  EXPECT_FALSE(path_clears_box(line({0.29, 0.0, 10.0}, {0.0, 0.0, -10.0}), kLo, kHi, 3.0));
  // Moving sideways: at x = 0.29 + 0.5 tau it is inside the x slab only while z is still above the
  // box (z = 10 - 10 tau > 0.25 for tau < 0.975): the z window rules it out.
  const Parabola late = line({0.29, 0.0, 10.0}, {0.5, 0.0, -10.0});
  EXPECT_FALSE(enters_box(late, kLo, kHi, 3.0));
  EXPECT_TRUE(path_clears_box(late, kLo, kHi, 3.0));
  // Crossing the x slab while z passes the box: enters.
  const Parabola crossing = line({-0.5, 0.0, 10.0}, {0.5, 0.0, -10.0});
  EXPECT_TRUE(enters_box(crossing, kLo, kHi, 3.0));
  EXPECT_FALSE(path_clears_box(crossing, kLo, kHi, 3.0));
}

TEST(BoxClearance, GrazingTheTopFaceIsNotCleared) {
  // Thrown so that its apex, y = 0.25 exactly, is reached at tau = 1 s, when it is at the centre
  // in x and z: it touches the top face.
  const double vy = 9.81;
  const Parabola p = line({0.0, 0.25 - 0.5 * 9.81, 10.0}, {0.0, vy, -10.0}, kG);
  EXPECT_TRUE(enters_box(p, kLo, kHi, 3.0));
  EXPECT_FALSE(path_clears_box(p, kLo, kHi, 3.0));
  // Its apex 1 cm above the box: cleared.
  const Parabola above = line({0.0, 0.26 - 0.5 * 9.81, 10.0}, {0.0, vy, -10.0}, kG);
  EXPECT_FALSE(enters_box(above, kLo, kHi, 3.0));
  EXPECT_TRUE(path_clears_box(above, kLo, kHi, 3.0));
}

TEST(BoxClearance, InDoubtOnBadInput) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Parabola far = line({10.0, 0.0, 10.0}, {0.0, 0.0, 1.0});
  EXPECT_TRUE(path_clears_box(far, kLo, kHi, 3.0));
  EXPECT_FALSE(path_clears_box(far, kLo, kHi, -1.0));
  EXPECT_FALSE(path_clears_box(far, kLo, kHi, nan));
  EXPECT_FALSE(path_clears_box(line({nan, 0.0, 10.0}, {0.0, 0.0, 1.0}), kLo, kHi, 3.0));
}

TEST(BoxClearance, NeverClearsAPathThatEntersTheBox) {
  std::mt19937_64 rng(13);
  int cleared = 0;
  int misses = 0;
  for (int n = 0; n < 100000; ++n) {
    Eigen::Vector3d lo;
    Eigen::Vector3d hi;
    double t_end = 0.0;
    const Parabola p = random_box_path(rng, lo, hi, t_end);
    const bool enters = enters_box(p, lo, hi, t_end);
    const bool clear = path_clears_box(p, lo, hi, t_end);
    ASSERT_FALSE(clear && enters) << "case " << n;
    misses += enters ? 0 : 1;
    cleared += clear ? 1 : 0;
  }
  EXPECT_GT(cleared, misses * 8 / 10) << cleared << " of " << misses;
}

FragmentState fragment_at(const Eigen::Vector3d& p, const Eigen::Vector3d& v, double radius) {
  FragmentState f;
  f.position_m = p;
  f.velocity_mps = v;
  f.radius_m = radius;
  return f;
}

TEST(BoxClearance, BatchAnswersAsOnePathAtATime) {
  // Seen from the world frame itself, the batch's paths are the single test's, bit for bit.
  std::mt19937_64 rng(14);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  BoxClearance batch;  // reused, as edge-min does
  for (const std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{5}, std::size_t{3001}}) {
    Eigen::Vector3d lo;
    Eigen::Vector3d hi;
    double t_end = 0.0;
    std::vector<Parabola> paths(n);
    std::vector<FragmentState> fragments(n);
    const Eigen::Vector3d a = 0.5 * 20.0 * u(rng) * random_unit(rng);
    const Parabola first = random_box_path(rng, lo, hi, t_end);  // fixes the box and t_end
    for (std::size_t i = 0; i < n; ++i) {
      Eigen::Vector3d lo_i;
      Eigen::Vector3d hi_i;
      double t_i = 0.0;
      paths[i] = i == 0 ? first : random_box_path(rng, lo_i, hi_i, t_i);
      paths[i].accel_mps2 = 2.0 * a;
      fragments[i] = fragment_at(paths[i].p0_m, paths[i].v0_mps, u(rng) < 0.5 ? 0.0 : 0.2 * u(rng));
    }
    const auto clears = batch.run(fragments, BoxFrame{}, a, lo, hi, t_end);
    ASSERT_EQ(clears.size(), n);
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Vector3d g = Eigen::Vector3d::Constant(fragments[i].radius_m);
      ASSERT_EQ(clears[i] != 0, path_clears_box(paths[i], lo - g, hi + g, t_end)) << i;
    }
  }
}

TEST(BoxClearance, BatchInAMovingRotatedFrameIsConservative) {
  // A camera-like frame: the batch turns world paths into it; none it clears enters the box.
  std::mt19937_64 rng(15);
  const Eigen::Vector3d forward = random_unit(rng);
  const Eigen::Vector3d right = forward.cross(Eigen::Vector3d::UnitY()).normalized();
  const Eigen::Vector3d up = right.cross(forward);
  const BoxFrame frame{{1.0, 1.6, -2.0}, {right, up, forward}, {0.0, 0.0, -2.0}};
  const Eigen::Vector3d a(0.5 * kG.dot(right), 0.5 * kG.dot(up), 0.5 * kG.dot(forward));
  const std::size_t n = 20001;
  std::vector<Parabola> local(n);
  std::vector<FragmentState> fragments(n);
  Eigen::Vector3d lo;
  Eigen::Vector3d hi;
  double t_end = 0.0;
  random_box_path(rng, lo, hi, t_end);
  for (std::size_t i = 0; i < n; ++i) {
    Eigen::Vector3d lo_i;
    Eigen::Vector3d hi_i;
    double t_i = 0.0;
    local[i] = random_box_path(rng, lo_i, hi_i, t_i);
    local[i].accel_mps2 = 2.0 * a;
    const Eigen::Vector3d& d = local[i].p0_m;
    const Eigen::Vector3d& v = local[i].v0_mps;
    fragments[i] =
        fragment_at(frame.origin_m + d.x() * right + d.y() * up + d.z() * forward,
                    frame.velocity_mps + v.x() * right + v.y() * up + v.z() * forward, 0.0);
  }
  BoxClearance batch;
  const auto clears = batch.run(fragments, frame, a, lo, hi, t_end);
  int cleared = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!clears[i]) continue;
    ++cleared;
    ASSERT_FALSE(enters_box(local[i], lo, hi, t_end)) << i;
  }
  EXPECT_GT(cleared, 0);
}

}  // namespace
}  // namespace fragsim
