#include "control/geometry/first_root.hpp"

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

// A quadratic's roots come in closed form (first_root.cpp, quadratic_root_between). Against the
// roots of the same coefficients in long double: each reported root within the simple-root
// tolerance 16 eps size / |p'(z)| + 4 eps |z| of a true one (the bound first_root.hpp states for
// the search; a close pair has small |p'| and so a wide tolerance), every true root with a
// report, in four families: spread roots, close pairs, a tangent touch perturbed, and roots from
// 1e-30 to 1e30.
TEST(FirstRoot, QuadraticRootsAgreeWithLongDouble) {
  using LD = long double;
  std::mt19937_64 rng(20261203);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const auto log_uniform = [&](double lo_exp, double hi_exp) {
    return std::pow(10.0, lo_exp + (hi_exp - lo_exp) * (u(rng) + 1.0) / 2.0);
  };
  int checked = 0;
  for (int family = 0; family < 4; ++family) {
    for (int n = 0; n < 5000; ++n) {
      double a = 10.0 * u(rng);
      double b = 10.0 * u(rng);
      double scale = 1.0 + std::abs(u(rng));
      if (family == 1) b = a + log_uniform(-10, -1) * u(rng);
      if (family == 3) {
        a = (u(rng) > 0 ? 1.0 : -1.0) * log_uniform(-30, 30);
        b = (u(rng) > 0 ? 1.0 : -1.0) * log_uniform(-30, 30);
        scale = log_uniform(-10, 10);
      }
      Quartic c{scale * a * b, -scale * (a + b), scale, 0.0, 0.0};
      if (family == 2) {  // (x - a)^2 + e, e from 1e-16 to 1e-4 of the terms, either sign
        c = {a * a, -2.0 * a, 1.0, 0.0, 0.0};
        c[0] += u(rng) * log_uniform(-16, -4) * (2.0 * a * a);
      }
      // The true roots of the rounded coefficients, in long double.
      const LD c2 = c[2], c1 = c[1], c0 = c[0];
      const LD disc = c1 * c1 - 4.0L * c2 * c0;
      const LD lo =
          -4.0L * std::max(std::abs(static_cast<LD>(a)), std::abs(static_cast<LD>(b))) - 1.0L;
      const double bound = static_cast<double>(-lo);
      const std::vector<double> found = real_roots(c, -bound, bound);
      std::vector<LD> truth;
      if (disc >= 0.0L) {
        const LD h = -0.5L * (c1 + std::copysign(std::sqrt(disc), c1));
        truth = {h / c2, c0 / h};
      }
      const auto tol = [&](LD z) {
        const LD size = std::abs(c0) + std::abs(c1) * std::abs(z) + std::abs(c2) * z * z;
        const LD slope = std::abs(c1 + 2.0L * c2 * z);
        return 16.0L * std::numeric_limits<double>::epsilon() * size / slope +
               4.0L * std::numeric_limits<double>::epsilon() * std::abs(z);
      };
      SCOPED_TRACE(::testing::Message() << "family " << family << " #" << n);
      for (const double x : found) {
        bool near_one = false;
        for (const LD z : truth) near_one |= std::abs(static_cast<LD>(x) - z) <= tol(z);
        // A touch within rounding is reported at the vertex with no true root nearby.
        const LD vertex = -c1 / (2.0L * c2);
        near_one |= truth.empty() &&
                    std::abs(static_cast<LD>(x) - vertex) <= 1e-7L * (1.0L + std::abs(vertex));
        EXPECT_TRUE(near_one) << "root " << x;
      }
      for (const LD z : truth) {
        if (!(std::abs(z) < -lo)) continue;
        bool reported = false;
        for (const double x : found) reported |= std::abs(static_cast<LD>(x) - z) <= tol(z);
        EXPECT_TRUE(reported) << "missed " << static_cast<double>(z);
      }
      ++checked;
      if (::testing::Test::HasFailure()) return;
    }
  }
  EXPECT_EQ(checked, 20000);
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

// A guess near the first crossing (edge's last contact time, a step on) finds the same crossing
// as the full search, to its accuracy: on random quartics the guess is the true first entry moved
// by up to 80% of the half width, and the answers agree to 1e-12 of the interval. A guess past an
// earlier crossing, or with the crossing outside its bracket, falls back to the full search and
// so gives its answer to the bit.
TEST(FirstRoot, FirstNonpositiveNearFindsTheSameCrossing) {
  std::mt19937_64 rng(32);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::normal_distribution<double> normal(0.0, 1.0);
  int warm = 0;
  for (int n = 0; n < 20000; ++n) {
    Quartic c{};
    for (double& x : c) x = normal(rng);
    if (c[4] == 0.0) continue;
    const double hi = 3.0 * std::abs(normal(rng)) + 0.1;
    const auto full = first_nonpositive(c, 0.0, hi);
    if (!full || *full == 0.0) continue;
    const double half_width = 0.05 * hi;
    const auto near =
        first_nonpositive_near(c, 0.0, hi, *full + 0.8 * half_width * u(rng), half_width);
    ASSERT_TRUE(near.has_value()) << n;
    EXPECT_NEAR(*near, *full, 1e-12 * hi) << n;
    warm += *near != *full ? 1 : 0;
    // A guess well past the first crossing: the full search's answer, bit for bit.
    const auto late = first_nonpositive_near(c, 0.0, hi, *full + 3.0 * half_width, half_width);
    EXPECT_EQ(late, full) << n;
  }
  // Roots at 0.5 and 2: guessing 2 must not skip the crossing at 0.5.
  const Quartic two = from_roots(0.5, 2.0, 3.0, 4.0);
  const auto first = first_nonpositive_near(two, 0.0, 2.5, 2.0, 0.1);
  ASSERT_TRUE(first.has_value());
  EXPECT_NEAR(*first, 0.5, 1e-14);
  EXPECT_EQ(first_nonpositive_near(two, 0.0, 2.5, std::nan(""), 0.1),
            first_nonpositive(two, 0.0, 2.5));
  EXPECT_GT(warm, 0);  // some answers came from the narrowed bracket (other last bits)
}

// The batch with guesses gives first_nonpositive_near's answers bit for bit.
TEST(FirstRoot, GuessesGiveTheSameAnswersAsOneAtATime) {
  std::mt19937_64 rng(33);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<Quartic> polys;
  std::vector<double> his, guesses;
  for (int n = 0; n < 4000; ++n) {
    Quartic c{};
    for (double& x : c) x = normal(rng);
    const double hi = 3.0 * std::abs(normal(rng)) + 0.1;
    const auto full = first_nonpositive(c, 0.0, hi);
    polys.push_back(c);
    his.push_back(hi);
    // Good guesses, poor ones and none.
    guesses.push_back(n % 3 == 0   ? std::nan("")
                      : n % 3 == 1 ? (full ? *full + 0.01 * normal(rng) : 1.0)
                                   : 3.0 * std::abs(normal(rng)));
  }
  FirstNonpositiveBatch batch;
  const auto answers = batch.run(polys, 0.0, his, guesses, 0.05);
  ASSERT_EQ(answers.size(), polys.size());
  for (std::size_t j = 0; j < polys.size(); ++j) {
    EXPECT_EQ(answers[j], first_nonpositive_near(polys[j], 0.0, his[j], guesses[j], 0.05)) << j;
  }
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
TEST(FirstRoot, SameAnswersBitForBitAsOneAtATime) {
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
