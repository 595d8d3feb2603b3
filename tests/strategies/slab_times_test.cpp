#include "control/strategies/slab_times.hpp"

#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>

#include "control/geometry/first_root.hpp"

namespace fragsim {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// slab_times.hpp's definition written plainly: t0, t1 and each bound's list_real_roots, sorted by
// insertion (at most six points), each piece between consecutive points kept where its midpoint
// is inside, and {t0} for a path that starts inside with nothing else in the set. slab_times
// must give these sets bit for bit.
Intervals definition(const AxisQuadratic& c, const AxisQuadratic& lo, const AxisQuadratic& hi,
                     double t0, double t1) {
  std::array<double, 6> pts;
  int np = 0;
  const auto add = [&pts, &np](double v) {
    int k = np++;
    for (; k > 0 && pts[static_cast<std::size_t>(k - 1)] > v; --k) {
      pts[static_cast<std::size_t>(k)] = pts[static_cast<std::size_t>(k - 1)];
    }
    pts[static_cast<std::size_t>(k)] = v;
  };
  add(t0);
  add(t1);
  for (const AxisQuadratic& bound : {lo, hi}) {
    for (const double r :
         list_real_roots({c.c0 - bound.c0, c.c1 - bound.c1, c.c2 - bound.c2, 0.0, 0.0}, t0, t1)) {
      if (np < static_cast<int>(pts.size())) add(r);
    }
  }
  Intervals out;
  for (int i = 0; i + 1 < np; ++i) {
    const double a = pts[static_cast<std::size_t>(i)];
    const double b = pts[static_cast<std::size_t>(i + 1)];
    const double m = 0.5 * (a + b);
    const double mid = c.at(m);
    if (!(b > a && mid >= lo.at(m) && mid <= hi.at(m))) continue;
    if (out.n > 0 && out.span[static_cast<std::size_t>(out.n - 1)][1] >= a) {
      out.span[static_cast<std::size_t>(out.n - 1)][1] = b;
    } else {
      out.append(a, b);
    }
  }
  const double v0 = c.at(t0);
  if (out.n == 0 && v0 >= lo.at(t0) && v0 <= hi.at(t0)) out.append(t0, t0);
  return out;
}

// Equal to the bit: the same pieces, each end the same double (signed zeros and NaNs told apart).
std::string difference(const Intervals& got, const Intervals& want) {
  if (got.n != want.n) {
    return "pieces " + std::to_string(got.n) + " vs " + std::to_string(want.n);
  }
  for (int i = 0; i < got.n; ++i) {
    for (int e = 0; e < 2; ++e) {
      const double g = got.span[static_cast<std::size_t>(i)][static_cast<std::size_t>(e)];
      const double w = want.span[static_cast<std::size_t>(i)][static_cast<std::size_t>(e)];
      if (std::bit_cast<std::uint64_t>(g) != std::bit_cast<std::uint64_t>(w)) {
        return "piece " + std::to_string(i) + " end " + std::to_string(e) + ": " +
               std::to_string(g) + " vs " + std::to_string(w);
      }
    }
  }
  return "";
}

TEST(SlabTimes, ALineCrossingAFixedSlab) {
  // 1 - t between 0 and 0.5: t in [0.5, 1].
  const Intervals s = slab_times(AxisQuadratic{1.0, -1.0, 0.0}, 0.0, 0.5, 2.0);
  ASSERT_EQ(s.n, 1);
  EXPECT_NEAR(s.span[0][0], 0.5, 1e-15);
  EXPECT_NEAR(s.span[0][1], 1.0, 1e-15);
}

TEST(SlabTimes, AParabolaLeavingAndComingBack) {
  // (t - 1)^2 between 0.25 and 4 over [0, 5]: |t - 1| in [0.5, 2], so [0, 0.5] and [1.5, 3].
  const Intervals s = slab_times(AxisQuadratic{1.0, -2.0, 1.0}, 0.25, 4.0, 5.0);
  ASSERT_EQ(s.n, 2);
  EXPECT_NEAR(s.span[0][0], 0.0, 1e-15);
  EXPECT_NEAR(s.span[0][1], 0.5, 1e-15);
  EXPECT_NEAR(s.span[1][0], 1.5, 1e-15);
  EXPECT_NEAR(s.span[1][1], 3.0, 1e-15);
}

TEST(SlabTimes, GrowingBoundsCatchAPathThatRunsAway) {
  // x(t) = 1 + t runs from a slab [-0.5, 0.5] that grows by t^2 on each side: inside while
  // 1 + t <= 0.5 + t^2, i.e. t^2 - t - 0.5 >= 0, t >= (1 + sqrt(3)) / 2 = 1.3660...
  const Intervals s = slab_times(AxisQuadratic{1.0, 1.0, 0.0}, AxisQuadratic{-0.5, 0.0, -1.0},
                                 AxisQuadratic{0.5, 0.0, 1.0}, 0.0, 3.0);
  ASSERT_EQ(s.n, 1);
  EXPECT_NEAR(s.span[0][0], 0.5 * (1.0 + std::sqrt(3.0)), 1e-15);
  EXPECT_EQ(s.span[0][1], 3.0);
}

TEST(SlabTimes, AnInstantInsideIsOnePoint) {
  const Intervals s = slab_times(AxisQuadratic{0.1, 5.0, 1.0}, AxisQuadratic{0.0, 0.0, 0.0},
                                 AxisQuadratic{1.0, 0.0, 0.0}, 0.25, 0.25);
  // 0.1 + 1.25 + 0.0625 = 1.4125 is above 1 at t = 0.25: outside.
  EXPECT_EQ(s.n, 0);
  const Intervals inside = slab_times(AxisQuadratic{0.1, 0.0, 0.0}, AxisQuadratic{0.0, 0.0, 0.0},
                                      AxisQuadratic{1.0, 0.0, 0.0}, 0.25, 0.25);
  ASSERT_EQ(inside.n, 1);
  EXPECT_EQ(inside.span[0][0], 0.25);
  EXPECT_EQ(inside.span[0][1], 0.25);
}

TEST(SlabTimes, ACrossingTheClosedFormCannotPlaceIsSearched) {
  // t^2 + 1e200 t - 1e200 crosses 0 once in [0, 3], near t = 1; its discriminant overflows, so
  // neither closed-form root is usable and the bracketed search finds it.
  const AxisQuadratic c{-1e200, 1e200, 1.0};
  const Intervals s = slab_times(c, 0.0, 1e300, 3.0);
  ASSERT_EQ(s.n, 1);
  EXPECT_NEAR(s.span[0][0], 1.0, 1e-15);
  EXPECT_EQ(s.span[0][1], 3.0);
  EXPECT_EQ(difference(s, definition(c, {0.0, 0.0, 0.0}, {1e300, 0.0, 0.0}, 0.0, 3.0)), "");
}

// A random coefficient of a random scale, now and then one of the values that take the rarer
// branches: zero (a bound parallel to the path: a linear or constant difference), the same as
// another coefficient, huge (a sample overflows), or not finite.
double coefficient(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> kind(0, 39);
  std::uniform_int_distribution<int> scale(-12, 12);
  switch (kind(rng)) {
    case 0:
    case 1:
    case 2:
      return 0.0;
    case 3:
      return unit(rng) * 1e300;
    case 4:
      return kind(rng) < 20 ? kInf : std::nan("");
    case 5:
      return -0.0;
    default:
      return unit(rng) * std::ldexp(1.0, scale(rng));
  }
}

// A slab test case built to hit each branch: random bounds; or bounds the path touches at t0 or
// is tangent to (a break point within rounding of zero); or a coordinate with the bounds'
// curvature (a linear difference).
struct Case {
  AxisQuadratic c, lo, hi;
  double t0, t1;
};
Case random_case(std::mt19937_64& rng) {
  std::uniform_int_distribution<int> kind(0, 5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Case k;
  k.c = {coefficient(rng), coefficient(rng), coefficient(rng)};
  k.lo = {coefficient(rng), coefficient(rng), coefficient(rng)};
  k.hi = {coefficient(rng), coefficient(rng), coefficient(rng)};
  k.t0 = unit(rng) < 0.7 ? 0.0 : unit(rng) - 0.2;
  k.t1 = unit(rng) < 0.05 ? k.t0 : k.t0 + 3.0 * unit(rng) - 0.1;
  switch (kind(rng)) {
    case 0:  // touches the lower bound at t0
      k.lo.c0 = k.c.at(k.t0) - k.lo.c1 * k.t0 - k.lo.c2 * k.t0 * k.t0;
      break;
    case 1: {  // tangent to the upper bound at a time inside: c - hi = a (t - s)^2
      const double s = k.t0 + (k.t1 - k.t0) * unit(rng);
      const double a = 1.0 + unit(rng);
      k.hi = {k.c.c0 - a * s * s, k.c.c1 + 2.0 * a * s, k.c.c2 - a};
      break;
    }
    case 2:  // the bounds curve as the path does: linear differences
      k.lo.c2 = k.c.c2;
      k.hi.c2 = k.c.c2;
      break;
    case 3:  // an ordinary slab about the path
      k.c = {unit(rng) - 0.5, 4.0 * unit(rng) - 2.0, unit(rng) - 0.5};
      k.lo = {-0.3 * unit(rng), 0.0, -unit(rng)};
      k.hi = {0.3 * unit(rng), 0.0, unit(rng)};
      k.t0 = 0.0;
      k.t1 = 2.0 * unit(rng);
      break;
    default:
      break;
  }
  return k;
}

TEST(SlabTimes, EveryBranchGivesTheDefinitionsSetsBitForBit) {
  std::mt19937_64 rng(37);
  int nonempty = 0;
  for (int i = 0; i < 200000; ++i) {
    const Case a = random_case(rng);
    const Intervals want_a = definition(a.c, a.lo, a.hi, a.t0, a.t1);
    nonempty += want_a.n > 0 ? 1 : 0;
    ASSERT_EQ(difference(slab_times(a.c, a.lo, a.hi, a.t0, a.t1), want_a), "") << "case " << i;
    // In pairs over a's interval, at both widths.
    Case b = random_case(rng);
    const Intervals want_b = definition(b.c, b.lo, b.hi, a.t0, a.t1);
    for (const bool wide : {true, false}) {
      Intervals got[2];
      slab_times(Slab{a.c, a.lo, a.hi}, Slab{b.c, b.lo, b.hi}, a.t0, a.t1, got, wide);
      ASSERT_EQ(difference(got[0], want_a), "") << "pair " << i << " wide " << wide;
      ASSERT_EQ(difference(got[1], want_b), "") << "pair " << i << " wide " << wide;
    }
  }
  // Not only empty sets: the random cases reach the pieces.
  EXPECT_GT(nonempty, 20000);
}

}  // namespace
}  // namespace fragsim
