// libFuzzer target: real_roots and first_nonpositive on a quartic over an interval.
//
// Input: 7 little-endian doubles c0 c1 c2 c3 c4 lo hi (bytes 0..55; missing bytes read as zero),
// then an optional form byte. If its bit 0 is set, c0..c3 are read as roots r1..r4 and c4 as the
// leading factor a, and the polynomial is a (x - r1)(x - r2)(x - r3)(x - r4) expanded in double:
// a cheap way for the fuzzer to reach multiple and clustered roots.
//
// Checks (__builtin_trap() on violation):
//  - always, for finite inputs: every root lies in [lo, hi] and the roots are sorted; the first
//    non-positive point, if any, lies in [lo, hi]; an empty interval (lo > hi) has neither;
//  - in the value-checked domain (below): |p(r)| <= tol(r) at every root r; p(t) <= tol(t) at the
//    first non-positive point t, and p > -tol at 64 points of [lo, t); if there is none, then
//    p(lo) > 0 as the library evaluates it (its own contract), p > -tol at 65 points of [lo, hi]
//    and no root was reported.
//
// Tolerance. p, the size of its terms S(x) = sum |c_i| |x|^i and that of its derivative's terms
// D(x) = sum i |c_i| |x|^(i-1) are evaluated here in long double (x87: 64-bit significand, and an
// exponent range that no product of five finite doubles leaves), so this "true" p is exact to
// ~1e-18 S. Two things let a correct answer miss p = 0:
//  - the library evaluates p in double with Horner's rule, whose rounding is at most
//    gamma_8 S ~ 4 eps S (Higham 5.1); every sign it judges can be wrong by that much;
//  - a root is a double: at best the nearest one, and a search stops on adjacent doubles or a
//    Newton step below eps |x|, so p there is off by up to |p'| times a spacing of doubles,
//    at most D(x) ulp(x) (<= 4 eps S(x) where doubles are normal, more among subnormals).
// tol(x) = 8 eps S(x) + 4 D(x) ulp(x) + DBL_MIN takes each term twice or more (the factor 4 also
// covers a root a few ulps off); the floor covers Horner steps that land among subnormals.
//
// Value-checked domain: every non-zero |c_i|, |lo|, |hi| in [1e-150, 1e150] and
// S(max(|lo|, |hi|)) <= 1e300. Outside it the library's double arithmetic may overflow (it then
// rescales) or underflow by more than the floor, which are limitations, not bugs; such inputs
// still run for crashes, sanitizer reports, hangs and the structural checks above.

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <vector>

#include "control/geometry/first_root.hpp"

namespace {

using fragsim::Quartic;

constexpr double kEps = DBL_EPSILON;
constexpr double kMinMagnitude = 1e-150;
constexpr double kMaxMagnitude = 1e150;
constexpr long double kMaxTerms = 1e300L;
constexpr int kSamples = 64;

void check(bool ok) {
  if (!ok) __builtin_trap();
}

struct Value {
  long double p;      // p(x)
  long double terms;  // S(x) = sum |c_i| |x|^i
  long double tol;    // tol(x), see the top of the file
};

Value value_at(const Quartic& c, double x) {
  const long double lx = x;
  const long double ax = std::fabs(lx);
  long double p = 0.0L;
  long double terms = 0.0L;
  long double slope_terms = 0.0L;  // D(x) = sum i |c_i| |x|^(i-1)
  for (int k = 4; k >= 0; --k) {
    const long double ck = c[static_cast<std::size_t>(k)];
    slope_terms = slope_terms * ax + terms;
    p = p * lx + ck;
    terms = terms * ax + std::fabs(ck);
  }
  const double ulp = std::nextafter(std::fabs(x), INFINITY) - std::fabs(x);
  return {p, terms, 8.0L * kEps * terms + 4.0L * slope_terms * ulp + DBL_MIN};
}

bool sane_magnitude(double v) {
  const double a = std::fabs(v);
  return a == 0.0 || (a >= kMinMagnitude && a <= kMaxMagnitude);
}

// a (x - r1)(x - r2)(x - r3)(x - r4), multiplied out one factor at a time in double.
Quartic from_roots(double a, const std::array<double, 4>& r) {
  Quartic c{a, 0.0, 0.0, 0.0, 0.0};  // c[0..k] holds the product of the first k factors
  for (std::size_t k = 0; k < 4; ++k) {
    for (std::size_t i = k + 1; i > 0; --i) c[i] = c[i - 1] - r[k] * c[i];
    c[0] = -r[k] * c[0];
  }
  return c;
}

// The i-th of n points spread from a to b (a <= b), within [a, b] despite rounding.
double spread(double a, double b, int i, int n) {
  const double x = a + (b - a) * (static_cast<double>(i) / static_cast<double>(n));
  return std::fmin(std::fmax(x, a), b);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::array<double, 7> v{};
  std::memcpy(v.data(), data, std::min(size, sizeof v));
  const bool root_form = size > sizeof v && (data[sizeof v] & 1) != 0;
  for (double x : v) {
    if (!std::isfinite(x)) return 0;
  }
  const Quartic c = root_form ? from_roots(v[4], {v[0], v[1], v[2], v[3]})
                              : Quartic{v[0], v[1], v[2], v[3], v[4]};
  for (double x : c) {
    if (!std::isfinite(x)) return 0;  // the expansion overflowed
  }
  const double lo = v[5];
  const double hi = v[6];

  const std::vector<double> roots = fragsim::real_roots(c, lo, hi);
  const std::optional<double> first = fragsim::first_nonpositive(c, lo, hi);

  if (!(lo <= hi)) {  // an empty interval holds no point
    check(roots.empty());
    check(!first.has_value());
    return 0;
  }
  for (std::size_t i = 0; i < roots.size(); ++i) {
    check(roots[i] >= lo && roots[i] <= hi);
    if (i > 0) check(roots[i - 1] <= roots[i]);
  }
  if (first) check(*first >= lo && *first <= hi);

  bool checked = sane_magnitude(lo) && sane_magnitude(hi);
  for (double x : c) checked = checked && sane_magnitude(x);
  if (!checked || value_at(c, std::fmax(std::fabs(lo), std::fabs(hi))).terms > kMaxTerms) {
    return 0;
  }

  for (double r : roots) {
    const Value at = value_at(c, r);
    check(std::fabs(at.p) <= at.tol);
  }
  if (first) {
    const double t = *first;
    const Value at = value_at(c, t);
    check(at.p <= at.tol);
    for (int i = 0; i < kSamples; ++i) {  // nothing non-positive before t
      const double x = spread(lo, t, i, kSamples);
      if (x >= t) break;
      const Value before = value_at(c, x);
      check(before.p > -before.tol);
    }
  } else {
    check(roots.empty());  // a root, even a touch, is a non-positive point
    check(fragsim::evaluate(c, lo) > 0.0);
    for (int i = 0; i <= kSamples; ++i) {
      const Value s = value_at(c, spread(lo, hi, i, kSamples));
      check(s.p > -s.tol);
    }
  }
  return 0;
}
