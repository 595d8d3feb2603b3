#pragma once
// Real roots of small polynomials on an interval, found by isolating monotone pieces between the
// roots of the derivative (recursively) and bisecting each sign change. Unlike the closed-form
// quartic formulas this keeps double roots (a path tangent to the ball) and clustered roots.

#include <array>
#include <optional>
#include <vector>

namespace fragsim {

// c[0] + c[1] x + ... + c[4] x^4; higher unused coefficients are zero.
using Quartic = std::array<double, 5>;

double evaluate(const Quartic& c, double x);

// Every real root in [lo, hi], ascending. A root of even multiplicity (the polynomial touches zero
// without crossing) is reported when |p| there is within rounding of zero.
std::vector<double> real_roots(const Quartic& c, double lo, double hi);

// The smallest x in [lo, hi] with p(x) <= 0 (lo itself if p(lo) <= 0), or nothing if p > 0 on
// the whole interval. "p <= 0" is judged with a tolerance of a few ulps of the terms' size, so a
// tangent touch counts.
std::optional<double> first_nonpositive(const Quartic& c, double lo, double hi);

}  // namespace fragsim
