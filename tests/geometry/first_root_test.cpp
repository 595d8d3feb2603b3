#include "geometry/first_root.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <random>
#include <span>
#include <vector>

namespace fragsim {
namespace {

// (x - a)(x - b)(x - c)(x - d) expanded.
Quartic from_roots(double a, double b, double c, double d) {
  return {a * b * c * d, -(a * b * c + a * b * d + a * c * d + b * c * d),
          a * b + a * c + a * d + b * c + b * d + c * d, -(a + b + c + d), 1.0};
}

TEST(FirstRoot, SimpleRootsInOrder) {
  const auto roots = real_roots(from_roots(-1.0, 0.5, 2.0, 3.0), -10.0, 10.0);
  ASSERT_EQ(roots.size(), 4u);
  EXPECT_NEAR(roots[0], -1.0, 1e-12);
  EXPECT_NEAR(roots[1], 0.5, 1e-12);
  EXPECT_NEAR(roots[2], 2.0, 1e-12);
  EXPECT_NEAR(roots[3], 3.0, 1e-12);
}

TEST(FirstRoot, FirstNonpositiveIsTheFirstEntry) {
  // Positive before 0.5, negative on (0.5, 2).
  const auto t = first_nonpositive(from_roots(0.5, 2.0, 3.0, 4.0), 0.0, 10.0);
  ASSERT_TRUE(t.has_value());
  EXPECT_NEAR(*t, 0.5, 1e-12);
}

TEST(FirstRoot, StartsInsideReturnsTheStart) {
  const auto t = first_nonpositive(from_roots(-1.0, 2.0, 5.0, 6.0), 0.0, 10.0);
  ASSERT_TRUE(t.has_value());
  EXPECT_EQ(*t, 0.0);
}

TEST(FirstRoot, DoubleRootIsATouch) {
  // (x - 1)^2 (x - 3)^2 >= 0 touches zero at 1 and 3 without crossing.
  const auto t = first_nonpositive(from_roots(1.0, 1.0, 3.0, 3.0), 0.0, 10.0);
  ASSERT_TRUE(t.has_value());
  EXPECT_NEAR(*t, 1.0, 1e-7);
  const auto roots = real_roots(from_roots(1.0, 1.0, 3.0, 3.0), 0.0, 10.0);
  ASSERT_EQ(roots.size(), 2u);
  EXPECT_NEAR(roots[0], 1.0, 1e-7);
  EXPECT_NEAR(roots[1], 3.0, 1e-7);
}

TEST(FirstRoot, QuadrupleRoot) {
  const auto t = first_nonpositive(from_roots(1.0, 1.0, 1.0, 1.0), 0.0, 2.0);
  ASSERT_TRUE(t.has_value());
  EXPECT_NEAR(*t, 1.0, 1e-3);  // a fourfold root is only determined to about eps^(1/4)
}

TEST(FirstRoot, NoRootInTheInterval) {
  EXPECT_FALSE(first_nonpositive(from_roots(5.0, 6.0, 7.0, 8.0), 0.0, 4.0).has_value());
  // Positive everywhere: x^4 + 1.
  EXPECT_FALSE(first_nonpositive({1.0, 0.0, 0.0, 0.0, 1.0}, -10.0, 10.0).has_value());
}

TEST(FirstRoot, ClusteredRoots) {
  // Rounding the coefficients alone moves a root r by up to about eps |terms(r)| / |p'(r)|; with
  // |p'| ~ 2e-9 here and terms ~ 500 that is ~5e-5: the tolerance is that bound, per root.
  const Quartic c = from_roots(2.000, 2.001, 2.002, 2.003);
  const auto roots = real_roots(c, 0.0, 4.0);
  ASSERT_EQ(roots.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    const double r = 2.0 + 0.001 * static_cast<double>(i);
    double slope = 1.0;
    for (std::size_t j = 0; j < 4; ++j) {
      if (j != i) slope *= r - (2.0 + 0.001 * static_cast<double>(j));
    }
    const double terms = 1 + 8 * r * (1 + 3 * r * (1 + 4 * r * (1 + 2 * r)));  // |coeffs| r^k
    const double bound = 8 * 2.2e-16 * terms / std::abs(slope);
    EXPECT_NEAR(roots[i], r, bound) << "root " << i;
  }
}

TEST(FirstRoot, LowerDegrees) {
  const auto lin = first_nonpositive({2.0, -1.0, 0.0, 0.0, 0.0}, 0.0, 5.0);  // 2 - x
  ASSERT_TRUE(lin.has_value());
  EXPECT_DOUBLE_EQ(*lin, 2.0);
  const auto quad = first_nonpositive({4.0, 0.0, -1.0, 0.0, 0.0}, 0.0, 5.0);  // 4 - x^2
  ASSERT_TRUE(quad.has_value());
  EXPECT_NEAR(*quad, 2.0, 1e-12);
}

TEST(FirstRoot, NearTouchIsJudgedAgainstRounding) {
  // (x - 1)^2 + e: Horner's error at 1 is ~4 eps |terms| ~ 2e-15. Clearly above it: no root;
  // below it: a touch, reported at the minimum; clearly negative: two roots 1 -+ sqrt(-e), the
  // first to eps |terms| / |p'| ~ 1e-8 (|p'| = 2 sqrt(-e)).
  auto near_square = [](double e) { return Quartic{1.0 + e, -2.0, 1.0, 0.0, 0.0}; };
  EXPECT_FALSE(first_nonpositive(near_square(1e-13), 0.0, 3.0).has_value());
  EXPECT_TRUE(real_roots(near_square(1e-13), 0.0, 3.0).empty());
  const auto touch = first_nonpositive(near_square(1e-16), 0.0, 3.0);
  ASSERT_TRUE(touch.has_value());
  EXPECT_NEAR(*touch, 1.0, 1e-15);  // the critical point -c1 / 2 c2, exact here
  const auto cross = first_nonpositive(near_square(-1e-13), 0.0, 3.0);
  ASSERT_TRUE(cross.has_value());
  EXPECT_NEAR(*cross, 1.0 - std::sqrt(1e-13), 1e-8);
  EXPECT_EQ(real_roots(near_square(-1e-13), 0.0, 3.0).size(), 2u);
}

TEST(FirstRoot, RootsAtTheEndsOfTheInterval) {
  const Quartic c = from_roots(1.0, 2.0, 3.0, 4.0);
  EXPECT_EQ(first_nonpositive(c, 1.0, 1.5), std::optional<double>(1.0));
  const auto roots = real_roots(c, 1.0, 4.0);
  ASSERT_EQ(roots.size(), 4u);
  EXPECT_EQ(roots.front(), 1.0);
  EXPECT_EQ(roots.back(), 4.0);
  // Entering exactly at the end: p(hi) = 0.
  const auto at_end = first_nonpositive(c, 0.0, 1.0);
  ASSERT_TRUE(at_end.has_value());
  EXPECT_EQ(*at_end, 1.0);
  EXPECT_EQ(first_nonpositive(c, 0.0, 0.0), std::nullopt);
}

TEST(FirstRoot, TinyRootInAWideInterval) {
  // A root at 1e-28 inside [-1e10, 1e10], 38 orders of magnitude below the interval: the simple
  // root is determined to 8 eps |terms| / |p'| = 8 eps 1e-28 (|p'| = 3, terms ~3e-28).
  const Quartic c = from_roots(1e-28, 0.5, 2.0, 3.0);
  const auto roots = real_roots(c, -1e10, 1e10);
  ASSERT_EQ(roots.size(), 4u);
  EXPECT_NEAR(roots[0], 1e-28, 1e-28 * 8 * 2.2e-16);
  const auto first = first_nonpositive(c, -1e10, 1e10);
  ASSERT_TRUE(first.has_value());
  EXPECT_NEAR(*first, 1e-28, 1e-28 * 8 * 2.2e-16);
}

TEST(FirstRoot, RootsWhereHornerOverflows) {
  // (x - 1e200)(x - 1): x^2 overflows near the large root, so p is evaluated there as
  // p(x) / x^2 = 1 - (1e200 + 1) / x + 1e200 / x^2.
  const Quartic c{1e200, -(1e200 + 1.0), 1.0, 0.0, 0.0};
  const auto roots = real_roots(c, -1e300, 1e300);
  ASSERT_EQ(roots.size(), 2u);
  EXPECT_NEAR(roots[0], 1.0, 4 * 2.2e-16);
  EXPECT_NEAR(roots[1], 1e200, 1e200 * 4 * 2.2e-16);
  // 1 - 1e-300 x^4 turns negative at 1e75, where x^4 = 1e300 and at the far end 1e320.
  const auto far = first_nonpositive({1.0, 0.0, 0.0, 0.0, -1e-300}, 1e70, 1e80);
  ASSERT_TRUE(far.has_value());
  EXPECT_NEAR(*far, 1e75, 1e75 * 8 * 2.2e-16);
  EXPECT_EQ(first_nonpositive({1.0, 0.0, 0.0, 0.0, 1e-300}, 1e70, 1e80), std::nullopt);
}

TEST(FirstRoot, UnusableInputGivesNothing) {
  const Quartic c = from_roots(0.5, 2.0, 3.0, 4.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_EQ(first_nonpositive(c, 2.0, 1.0), std::nullopt);  // lo > hi
  EXPECT_EQ(first_nonpositive(c, 0.0, inf), std::nullopt);
  EXPECT_EQ(first_nonpositive(c, nan, 1.0), std::nullopt);
  EXPECT_EQ(first_nonpositive({nan, 1.0, 0.0, 0.0, 0.0}, 0.0, 1.0), std::nullopt);
  EXPECT_TRUE(real_roots({1.0, inf, 0.0, 0.0, 0.0}, 0.0, 1.0).empty());
  // Constants: all of the interval or nothing.
  EXPECT_EQ(first_nonpositive({-1.0, 0.0, 0.0, 0.0, 0.0}, 3.0, 5.0), std::optional<double>(3.0));
  EXPECT_EQ(first_nonpositive({1.0, 0.0, 0.0, 0.0, 0.0}, 3.0, 5.0), std::nullopt);
}

TEST(FirstRoot, FirstNonpositiveAgreesWithRealRoots) {
  // Two paths through the code (first_nonpositive adds a Bernstein shortcut and stops at the
  // first entry): for p(lo) clearly positive, the first entry is the first root real_roots
  // reports, or none. Same arithmetic on the same pieces, so the same double.
  std::mt19937_64 rng(3);
  std::normal_distribution<double> normal(0.0, 1.0);
  int entries = 0;
  for (int n = 0; n < 20000; ++n) {
    Quartic c{};
    for (double& x : c) x = normal(rng);
    const double lo = 2.0 * normal(rng);
    const double hi = lo + std::abs(3.0 * normal(rng));
    const double p_lo = evaluate(c, lo);
    const double size_lo =
        std::abs(c[0]) +
        std::abs(lo) *
            (std::abs(c[1]) +
             std::abs(lo) * (std::abs(c[2]) +
                             std::abs(lo) * (std::abs(c[3]) + std::abs(lo) * std::abs(c[4]))));
    if (p_lo <= 16 * 2.2e-16 * size_lo) continue;  // starts inside, or too close to judge here
    const auto first = first_nonpositive(c, lo, hi);
    const auto roots = real_roots(c, lo, hi);
    ASSERT_EQ(first.has_value(), !roots.empty()) << n;
    if (first) {
      EXPECT_EQ(*first, roots.front()) << n;
      ++entries;
    }
  }
  EXPECT_GT(entries, 1000);
}

TEST(FirstRoot, ListedRootsAreRealRoots) {
  // The allocation-free form (edge-min's inner loop) returns the very same doubles.
  std::mt19937_64 rng(4);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (int n = 0; n < 20000; ++n) {
    Quartic c{};
    for (double& x : c) x = normal(rng);
    if (n % 3 == 0) c[4] = c[3] = 0.0;  // the quadratics edge-min solves
    const double lo = 2.0 * normal(rng);
    const double hi = lo + std::abs(3.0 * normal(rng));
    const std::vector<double> roots = real_roots(c, lo, hi);
    const RootList list = list_real_roots(c, lo, hi);
    ASSERT_EQ(std::vector<double>(list.begin(), list.end()), roots) << n;
  }
  EXPECT_EQ(
      list_real_roots({1.0, std::numeric_limits<double>::infinity(), 0.0, 0.0, 0.0}, 0.0, 1.0).n,
      0u);
}

}  // namespace
}  // namespace fragsim

namespace fragsim {
namespace {

// The batch must give first_nonpositive's answers bit for bit (`edge`'s pinned results rest on
// it): every kind of case the scalar path has, in one batch so that their searches interleave.
TEST(FirstRootBatch, SameAnswersBitForBitAsOneAtATime) {
  std::vector<Quartic> polys = {
      from_roots(0.5, 2.0, 3.0, 4.0),      // an entry at 0.5
      from_roots(-1.0, 2.0, 5.0, 6.0),     // inside at the start: 0
      from_roots(1.0, 1.0, 3.0, 4.0),      // a double root: a touch at 1
      from_roots(11.0, 12.0, 13.0, 14.0),  // no root in [0, 10]
      {1.0, -2.0, 1.0, 0.0, 0.0},          // a quadratic: the scalar path
      {0.0, 0.0, 0.0, 0.0, 0.0},           // a constant
      {std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0, 0.0, 1.0},  // unusable
  };
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> root(-30.0, 40.0);
  std::uniform_real_distribution<double> scale(0.1, 100.0);
  for (int k = 0; k < 2000; ++k) {
    Quartic q = from_roots(root(rng), root(rng), root(rng), root(rng));
    const double s = scale(rng);
    for (double& c : q) c *= s;
    // Lift some off the axis so that they touch, graze or miss.
    if (k % 3 == 0) q[0] += scale(rng);
    polys.push_back(q);
  }
  std::vector<double> hi(polys.size(), 10.0);
  hi[3] = 10.0;
  FirstNonpositiveBatch batch;
  const auto got = batch.run(polys, 0.0, hi);
  ASSERT_EQ(got.size(), polys.size());
  int roots = 0;
  for (std::size_t j = 0; j < polys.size(); ++j) {
    const auto want = first_nonpositive(polys[j], 0.0, hi[j]);
    ASSERT_EQ(got[j].has_value(), want.has_value()) << j;
    if (!want) continue;
    ++roots;
    EXPECT_EQ(std::bit_cast<std::uint64_t>(*got[j]), std::bit_cast<std::uint64_t>(*want)) << j;
  }
  EXPECT_NEAR(*got[0], 0.5, 1e-12);
  EXPECT_EQ(*got[1], 0.0);
  EXPECT_NEAR(*got[2], 1.0, 1e-6);
  EXPECT_FALSE(got[3].has_value());
  EXPECT_EQ(*got[4], 1.0);
  EXPECT_FALSE(got[6].has_value());
  // Both outcomes are well represented among the random ones.
  EXPECT_GT(roots, 500);
  EXPECT_LT(roots, 1900);
  // The work space is reused: a second, smaller batch gives its own answers.
  const auto again = batch.run(std::span<const Quartic>(polys).first(1), 0.0,
                               std::span<const double>(hi).first(1));
  ASSERT_EQ(again.size(), 1u);
  EXPECT_NEAR(*again[0], 0.5, 1e-12);
}

}  // namespace
}  // namespace fragsim
