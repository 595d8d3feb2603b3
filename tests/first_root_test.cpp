#include "strategies/first_root.hpp"

#include <gtest/gtest.h>

#include <cmath>

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

}  // namespace
}  // namespace fragsim
