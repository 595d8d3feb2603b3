#pragma once
// Real roots of small polynomials on an interval, found by isolating monotone pieces between the
// roots of the derivative (recursively) and solving each sign change by Newton's method inside
// the bracket. Unlike the closed-form quartic formulas this keeps double roots (a path tangent to
// the ball) and clustered roots.
//
// p is evaluated by Horner's rule, whose error is at most ~4 eps size(x), where
// size(x) = sum |c_k| |x|^k. A root is found to within what that error allows (about
// 8 eps size / |p'| for a simple root, (8 eps size / |p^(m) / m!|)^(1/m) for a root of multiplicity
// m, plus an ulp). Where Horner's form would overflow (|x| or the coefficients near the top of the
// double range) p is evaluated as p(x) / x^d instead. tests/geometry/first_root_reference_test.cpp
// checks it against a long-double companion-matrix reference.

#include <array>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "control/memory/memory_resource.hpp"

namespace fragsim {

// c[0] + c[1] x + ... + c[4] x^4; higher unused coefficients are zero.
using Quartic = std::array<double, 5>;

// Horner's rounding error on a polynomial of degree d is at most gamma_2d |terms| ~ d eps |terms|
// (Higham, "Accuracy and Stability of Numerical Algorithms", section 5.1), 4 eps for a quartic. A
// value within kRootZeroTolerance times the size of its terms is indistinguishable from zero.
inline constexpr double kRootZeroTolerance = 4.0 * std::numeric_limits<double>::epsilon();

// Horner's rule, as is.
double evaluate(const Quartic& c, double x);

// Every real root in [lo, hi], ascending. A root of even multiplicity (the polynomial touches zero
// without crossing) is reported when |p| there is within rounding of zero (4 eps size), and once.
// Nothing when lo > hi or an input is not finite.
std::vector<double> real_roots(const Quartic& c, double lo, double hi);

// real_roots without allocating, for hot loops (the same roots in a fixed array).
struct RootList {
  // Room for every root the search can report; only the first n are set (a hot loop's list is
  // not cleared first).
  std::array<double, 8> x;
  std::size_t n = 0;
  const double* begin() const { return x.data(); }
  const double* end() const { return x.data() + n; }
};
RootList list_real_roots(const Quartic& c, double lo, double hi);

// The smallest x in [lo, hi] with p(x) <= 0 (lo itself if p(lo) <= 0), or nothing if p > 0 on
// the whole interval. "p <= 0" is judged with a tolerance of 4 eps size(x), so a tangent touch
// counts. Nothing when lo > hi or an input is not finite (the caller's state checks report that).
// Allocation-free; a Bernstein-coefficient test settles most paths that stay clear of the ball
// without a search.
std::optional<double> first_nonpositive(const Quartic& c, double lo, double hi);

// first_nonpositive with a guess of where the first crossing is (say the last step's, moved on by a
// step). When p is certified positive on [lo, guess - half_width] (its Bernstein coefficients),
// negative at guess + half_width and decreasing in between (its derivative's), the crossing is
// searched in that bracket alone, skipping the derivative's roots; otherwise, or for a degree other
// than 4, first_nonpositive itself. The same crossing either way, to the search's accuracy (not
// always the same last bits, as the bracket differs). A NaN guess is no guess.
std::optional<double> first_nonpositive_near(const Quartic& c, double lo, double hi, double guess,
                                             double half_width);

// first_nonpositive of many polynomials, c[j] on [lo, hi[j]], with the same answers bit for bit.
// The root searches of all of them (those of the derivative that bracket each, then each one's
// first crossing) are advanced in turn, so the processor overlaps their chains of dependent
// operations where one search alone waits on each. Keeps its work space between calls.
class FirstNonpositiveBatch {
 public:
  // Its work space is allocated from `mem`.
  explicit FirstNonpositiveBatch(MemoryResource* mem = default_memory_resource());
  ~FirstNonpositiveBatch();
  FirstNonpositiveBatch(const FirstNonpositiveBatch&);
  FirstNonpositiveBatch& operator=(const FirstNonpositiveBatch&);

  // One answer per polynomial, in order; valid until the next call.
  std::span<const std::optional<double>> run(std::span<const Quartic> c, double lo,
                                             std::span<const double> hi);
  // The same with a guess per polynomial (NaN for none), as first_nonpositive_near and with its
  // answers, bit for bit.
  std::span<const std::optional<double>> run(std::span<const Quartic> c, double lo,
                                             std::span<const double> hi,
                                             std::span<const double> guess, double half_width);
  // Room for runs over up to n polynomials.
  void reserve(std::size_t n);

 private:
  struct Work;
  struct Release {
    void operator()(Work* w) const;
  };
  std::unique_ptr<Work, Release> work_;
};

}  // namespace fragsim
