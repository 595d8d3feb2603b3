#include "strategies/first_root.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fragsim {
namespace {

int degree(const Quartic& c) {
  for (int d = 4; d > 0; --d) {
    if (c[static_cast<std::size_t>(d)] != 0.0) return d;
  }
  return 0;
}

Quartic derivative(const Quartic& c) {
  return {c[1], 2.0 * c[2], 3.0 * c[3], 4.0 * c[4], 0.0};
}

// Size of the terms at x: the scale against which "p(x) is zero" is judged.
double magnitude(const Quartic& c, double x) {
  const double ax = std::abs(x);
  return std::abs(c[0]) +
         ax *
             (std::abs(c[1]) + ax * (std::abs(c[2]) + ax * (std::abs(c[3]) + ax * std::abs(c[4]))));
}

// Horner's rounding error on a quartic is at most about 8 u |terms| (u = eps / 2): a value that
// small is indistinguishable from zero.
constexpr double kZeroTolerance = 4.0 * std::numeric_limits<double>::epsilon();

bool near_zero(const Quartic& c, double x) {
  return std::abs(evaluate(c, x)) <= kZeroTolerance * magnitude(c, x);
}

// The root of a polynomial that is monotone on [a, b] with p(a) and p(b) of opposite signs (or one
// of them zero). Bisection to the last representable midpoint: ~60 halvings at most.
double bisect(const Quartic& c, double a, double b) {
  double fa = evaluate(c, a);
  if (fa == 0.0) return a;
  for (int i = 0; i < 200; ++i) {
    const double m = 0.5 * (a + b);
    if (m <= a || m >= b) break;
    const double fm = evaluate(c, m);
    if (fm == 0.0) return m;
    if ((fm < 0.0) == (fa < 0.0)) {
      a = m;
      fa = fm;
    } else {
      b = m;
    }
  }
  return 0.5 * (a + b);
}

// The interval's end points with the derivative's roots between them: p is monotone between
// consecutive break points.
std::vector<double> break_points(const Quartic& c, double lo, double hi) {
  std::vector<double> pts{lo};
  if (degree(c) >= 2) {
    for (double r : real_roots(derivative(c), lo, hi)) {
      if (r > pts.back() && r < hi) pts.push_back(r);
    }
  }
  pts.push_back(hi);
  return pts;
}

}  // namespace

double evaluate(const Quartic& c, double x) {
  return c[0] + x * (c[1] + x * (c[2] + x * (c[3] + x * c[4])));
}

std::vector<double> real_roots(const Quartic& c, double lo, double hi) {
  std::vector<double> roots;
  if (!(lo <= hi)) return roots;
  const int d = degree(c);
  if (d == 0) return roots;  // a constant: no isolated roots (all or none)
  if (d == 1) {
    const double r = -c[0] / c[1];
    if (r >= lo && r <= hi) roots.push_back(r);
    return roots;
  }
  const std::vector<double> pts = break_points(c, lo, hi);
  auto add = [&roots](double r) {
    if (roots.empty() || r > roots.back()) roots.push_back(r);
  };
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const double a = pts[i];
    const double b = pts[i + 1];
    // A break point where p vanishes to rounding is a root: a double root is found here.
    const bool za = near_zero(c, a);
    const bool zb = near_zero(c, b);
    if (za) add(a);
    const double fa = evaluate(c, a);
    const double fb = evaluate(c, b);
    if (!za && !zb && ((fa < 0.0) != (fb < 0.0))) add(bisect(c, a, b));
    if (zb && i + 2 == pts.size()) add(b);
  }
  return roots;
}

std::optional<double> first_nonpositive(const Quartic& c, double lo, double hi) {
  if (!(lo <= hi)) return std::nullopt;
  auto nonpositive = [&c](double x) { return evaluate(c, x) <= 0.0 || near_zero(c, x); };
  if (nonpositive(lo)) return lo;
  if (degree(c) == 0) return std::nullopt;
  const std::vector<double> pts = break_points(c, lo, hi);
  for (std::size_t i = 1; i < pts.size(); ++i) {
    if (nonpositive(pts[i])) {
      // A break point within rounding of zero is a touch (a double root at a critical point):
      // it is exact there, while bisection would stop up to sqrt(eps) early, where rounding
      // first makes p look non-positive.
      if (near_zero(c, pts[i])) return pts[i];
      // p > 0 at pts[i-1] and < 0 at pts[i], monotone between: one crossing.
      return bisect(c, pts[i - 1], pts[i]);
    }
  }
  return std::nullopt;
}

}  // namespace fragsim
