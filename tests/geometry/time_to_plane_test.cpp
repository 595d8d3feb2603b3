#include "control/geometry/time_to_plane.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <optional>
#include <random>

#include "control/strategies/lanes.hpp"

namespace fragsim {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

std::optional<double> plane_time(double c, double b, double a) {
  return time_to_plane_s(AxisQuadratic{c, b, a});
}

TEST(TimeToPlane, HandValues) {
  // Thrown up from the plane at 10 m/s under 10 m/s^2: back down through it at 2 s, not at 0.
  EXPECT_EQ(plane_time(0.0, 10.0, -5.0), 2.0);
  // Dropped from 5 m: 1 s.
  EXPECT_EQ(plane_time(5.0, 0.0, -5.0), 1.0);
  // Without gravity along the normal: the line's root, falling only.
  EXPECT_EQ(plane_time(1.0, -2.0, 0.0), 0.5);
  EXPECT_FALSE(plane_time(1.0, 2.0, 0.0));
  EXPECT_FALSE(plane_time(1.0, 0.0, 0.0));
}

TEST(TimeToPlane, NothingWhenTheCrossingIsNotAheadOrNotDown) {
  // Below the plane with a peak under it: no real root.
  EXPECT_FALSE(plane_time(-10.0, 0.0, -5.0));
  // Below the plane, rising through it at 0.5 s and falling back through it at 1.5 s.
  EXPECT_EQ(plane_time(-3.75, 10.0, -5.0), 1.5);
  // Rising to touch it at 1 s and falling away: a touch is no crossing.
  EXPECT_FALSE(plane_time(-5.0, 10.0, -5.0));
  // Gravity pointing up: it dips through the plane and comes back up, so it does not stay down.
  EXPECT_FALSE(plane_time(1.0, -10.0, 5.0));
  EXPECT_FALSE(plane_time(-1.0, 0.0, 5.0));
  // Non-finite input: nothing.
  EXPECT_FALSE(plane_time(kNaN, -1.0, -5.0));
  EXPECT_FALSE(plane_time(1.0, kNaN, -5.0));
}

// The answer is the later root, where the path falls: checked against the quadratic itself.
TEST(TimeToPlane, AnswerIsTheLaterFallingRoot) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-20.0, 20.0);
  int found = 0;
  for (int n = 0; n < 10000; ++n) {
    const double c = u(rng);
    const double b = u(rng);
    const double a = -std::abs(u(rng)) * 0.5;
    const std::optional<double> t = plane_time(c, b, a);
    if (!t) continue;
    ++found;
    const long double tl = *t;
    const long double h = c + tl * (b + tl * a);
    const double size = std::abs(c) + *t * (std::abs(b) + *t * std::abs(a));
    EXPECT_LE(std::abs(static_cast<double>(h)), 1e-13 * size) << c << " " << b << " " << a;
    EXPECT_LT(b + 2.0 * a * *t, 0.0);
    EXPECT_GT(*t, 0.0);
    // No later root: h stays below the plane after it (a < 0).
    const double later = *t * 1.001 + 1e-9;
    EXPECT_LT(c + later * (b + later * a), 1e-12 * size);
  }
  EXPECT_GT(found, 5000);
}

std::uint64_t bits(double x) {
  return std::bit_cast<std::uint64_t>(x);
}

// Two paths at once give each path's one-path answer, bit for bit, edge cases included.
TEST(TimeToPlane, LanesMatchOnePathBitForBit) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-20.0, 20.0);
  const double specials[] = {0.0, -0.0, 1e-300, -1e-300, 1e300, -1e300, kInf, -kInf, kNaN};
  const auto pick = [&](int k) {
    return k % 5 == 0 ? specials[(k / 5) % std::size(specials)] : u(rng);
  };
  const double none = 123.0;
  for (int n = 0; n < 20000; ++n) {
    const double a = n % 7 == 0 ? 0.0 : (n % 11 == 0 ? pick(n) : 0.5 * u(rng));
    const double b0 = pick(n + 1);
    const double b1 = pick(n + 2);
    const double c0 = pick(n + 3);
    const double c1 = pick(n + 4);
    double out[2];
    lanes::store(out, time_to_plane_s<lanes::LaneOps>(a, lanes::Lanes{b0, b1}, lanes::Lanes{c0, c1},
                                                      lanes::broadcast(none)));
    EXPECT_EQ(bits(out[0]), bits(time_to_plane_s<ScalarOps>(a, b0, c0, none)));
    EXPECT_EQ(bits(out[1]), bits(time_to_plane_s<ScalarOps>(a, b1, c1, none)));
  }
}

}  // namespace
}  // namespace fragsim
