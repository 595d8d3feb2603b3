// The first-root solver against references it shares no code with: the eigenvalues of the
// companion matrix in long double (Eigen's PolynomialSolver), on the hard quartics of the
// quartic-solver literature and on random ones; and the ball-contact classification against a
// brute-force, certified minimisation of the distance to the ball along random ballistic paths.
//
// Tolerances come from conditioning. Horner's error on a quartic is at most 4 eps size(x), with
// size(x) = sum |c_k| |x|^k, and the zero judgement adds as much again; so a root of
// multiplicity m whose Taylor coefficient there is a_m moves by at most (8 eps size / |a_m|)^(1/m)
// (a simple root: 8 eps size / |p'|). The tests allow twice that, plus 4 ulps of the root.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <cstdio>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <unsupported/Eigen/Polynomials>
#include <vector>

#include "control/geometry/first_root.hpp"
#include "control/strategies/collision_prediction.hpp"

namespace fragsim {
namespace {

using LD = long double;
using CLD = std::complex<LD>;

constexpr LD kEps = std::numeric_limits<double>::epsilon();
constexpr LD kTolFactor = 16.0L;  // twice the 8 eps bound of the header comment

template <typename T>
T horner(const Quartic& c, T x) {
  T p = T(c[4]);
  for (int k = 3; k >= 0; --k) p = p * x + T(c[static_cast<std::size_t>(k)]);
  return p;
}

// sum |c_k| |x|^k in long double.
LD size_at(const Quartic& c, LD ax) {
  LD s = 0.0L;
  for (int k = 4; k >= 0; --k)
    s = s * ax + std::fabs(static_cast<LD>(c[static_cast<std::size_t>(k)]));
  return s;
}

// The Taylor coefficient a_m = p^(m)(x) / m! of c at x, in long double.
CLD taylor(const Quartic& c, CLD x, int m) {
  static constexpr int kBinom[5][5] = {
      {1, 0, 0, 0, 0}, {1, 1, 0, 0, 0}, {1, 2, 1, 0, 0}, {1, 3, 3, 1, 0}, {1, 4, 6, 4, 1}};
  CLD a = 0.0L;
  for (int k = 4; k >= m; --k) {
    a = a * x + static_cast<LD>(kBinom[k][m]) * static_cast<LD>(c[static_cast<std::size_t>(k)]);
  }
  return a;
}

// How far rounding may move a root of multiplicity m at x.
LD root_tolerance(const Quartic& c, CLD x, int m) {
  const LD ax = std::abs(x);
  const LD am = std::abs(taylor(c, x, m));
  const LD spread = std::pow(kTolFactor * kEps * size_at(c, ax) / am, 1.0L / static_cast<LD>(m));
  return spread + 4.0L * kEps * ax;
}

// (x - r_1)...(x - r_4) in complex long double, real parts rounded to double.
Quartic from_roots(const std::array<CLD, 4>& r) {
  std::array<CLD, 5> e{CLD(1.0L), 0.0L, 0.0L, 0.0L, 0.0L};  // ascending, degree grows
  for (const CLD& root : r) {
    for (int k = 4; k >= 1; --k)
      e[static_cast<std::size_t>(k)] =
          e[static_cast<std::size_t>(k - 1)] - root * e[static_cast<std::size_t>(k)];
    e[0] = -root * e[0];
  }
  Quartic c;
  for (int k = 0; k < 5; ++k)
    c[static_cast<std::size_t>(k)] = static_cast<double>(e[static_cast<std::size_t>(k)].real());
  return c;
}

// Fujiwara's bound on the moduli of the roots of a monic quartic, doubled.
double root_bound(const Quartic& c) {
  LD b = 0.0L;
  for (int k = 0; k < 4; ++k) {
    LD ratio = std::fabs(static_cast<LD>(c[static_cast<std::size_t>(k)]) / static_cast<LD>(c[4]));
    if (k == 0) ratio /= 2.0L;
    b = std::max(b, std::pow(ratio, 1.0L / static_cast<LD>(4 - k)));
  }
  return static_cast<double>(4.0L * b);
}

struct HardCase {
  std::string name;
  std::array<CLD, 4> roots;  // the roots the polynomial is built from (repeated when multiple)
};

CLD re(LD x) {
  return {x, 0.0L};
}

// Strobach (J. Comput. Appl. Math. 234, 2010), Flocke (ACM TOMS 41(4), 2015) and the
// collection of Orellana & De Michele (ACM TOMS 46(2), 2020, cases 1-22 by their numbers), plus
// tangent and clustered roots of our own.
std::vector<HardCase> hard_cases() {
  return {
      {"(x-1)^4", {re(1), re(1), re(1), re(1)}},
      {"(x-1)^2 (x-3)^2", {re(1), re(1), re(3), re(3)}},
      {"(x-0.1)^2 (x-0.3)^2", {re(0.1L), re(0.1L), re(0.3L), re(0.3L)}},
      {"(x-1.1)^3 (x-2)", {re(1.1L), re(1.1L), re(1.1L), re(2)}},
      {"ODM 1: 1e9 1e6 1e3 1", {re(1e9L), re(1e6L), re(1e3L), re(1)}},
      {"ODM 2: 2.003 2.002 2.001 2", {re(2.003L), re(2.002L), re(2.001L), re(2)}},
      {"ODM 3: 1e53 1e50 1e49 1e47", {re(1e53L), re(1e50L), re(1e49L), re(1e47L)}},
      {"ODM 4: 1e14 2 1 -1", {re(1e14L), re(2), re(1), re(-1)}},
      {"ODM 5: -2e7 1e7 1 -1", {re(-2e7L), re(1e7L), re(1), re(-1)}},
      {"ODM 6: 1e7 -1e6 1+-i", {re(1e7L), re(-1e6L), CLD(1, 1), CLD(1, -1)}},
      {"ODM 7: -7 -4 -1e6+-1e5i", {re(-7), re(-4), CLD(-1e6L, 1e5L), CLD(-1e6L, -1e5L)}},
      {"ODM 8: 1e8 11 1e3+-i", {re(1e8L), re(11), CLD(1e3L, 1), CLD(1e3L, -1)}},
      {"ODM 9: 1e7+-1e6i 1+-2i", {CLD(1e7L, 1e6L), CLD(1e7L, -1e6L), CLD(1, 2), CLD(1, -2)}},
      {"ODM 10: 1e4+-3i -7+-1e3i", {CLD(1e4L, 3), CLD(1e4L, -3), CLD(-7, 1e3L), CLD(-7, -1e3L)}},
      {"ODM 11: 1.001+-4.998i 1+-5.001i",
       {CLD(1.001L, 4.998L), CLD(1.001L, -4.998L), CLD(1, 5.001L), CLD(1, -5.001L)}},
      {"ODM 12: 1e3+-3i 1e3+-i", {CLD(1e3L, 3), CLD(1e3L, -3), CLD(1e3L, 1), CLD(1e3L, -1)}},
      {"ODM 13: 2+-1e4i 1+-1e3i", {CLD(2, 1e4L), CLD(2, -1e4L), CLD(1, 1e3L), CLD(1, -1e3L)}},
      {"ODM 14: 1000^4", {re(1e3L), re(1e3L), re(1e3L), re(1e3L)}},
      {"ODM 15: 1000^3 2^-48", {re(1e3L), re(1e3L), re(1e3L), re(std::ldexp(1.0L, -48))}},
      {"ODM 16: 1e16+-1e7i 1+-0.1i",
       {CLD(1e16L, 1e7L), CLD(1e16L, -1e7L), CLD(1, 0.1L), CLD(1, -0.1L)}},
      {"ODM 17: 1e4 10001 10010 10100", {re(1e4L), re(10001), re(10010), re(10100)}},
      {"ODM 18: 4e5+-3e2i 3e4+-7e3i",
       {CLD(4e5L, 3e2L), CLD(4e5L, -3e2L), CLD(3e4L, 7e3L), CLD(3e4L, -7e3L)}},
      {"ODM 19: 1e44 1e30^2 1", {re(1e44L), re(1e30L), re(1e30L), re(1)}},
      {"ODM 20: 1e14 1e7^2 1", {re(1e14L), re(1e7L), re(1e7L), re(1)}},
      {"ODM 21: 1e15 1e7^2 1", {re(1e15L), re(1e7L), re(1e7L), re(1)}},
      {"ODM 22: 1e154 1e152 10 1", {re(1e154L), re(1e152L), re(10), re(1)}},
  };
}

// The eigenvalues of the companion matrix in long double (Eigen's PolynomialSolver). Their error
// is relative to the largest root, so small roots are taken from the reversed polynomial
// x^4 p(1/x), whose roots are the reciprocals: `reversed` returns those reciprocals.
std::vector<CLD> companion_roots(const Quartic& c, bool reversed) {
  Eigen::Matrix<LD, 5, 1> poly;
  for (int k = 0; k < 5; ++k) {
    poly[k] = static_cast<LD>(c[static_cast<std::size_t>(reversed ? 4 - k : k)]);
  }
  Eigen::PolynomialSolver<LD, 4> solver(poly);
  std::vector<CLD> roots;
  for (int i = 0; i < 4; ++i) {
    roots.push_back(reversed ? CLD(1.0L) / solver.roots()[i] : solver.roots()[i]);
  }
  return roots;
}

// Damped complex Newton steps on the double coefficients in long double (halved until they
// reduce |p|): the reference for a simple root. (A cluster is left alone: its centroid is
// accurate where its members are not.)
CLD polish(const Quartic& c, CLD z) {
  for (int it = 0; it < 100; ++it) {
    const CLD p = horner<CLD>(c, z);
    const CLD dp = taylor(c, z, 1);
    if (p == CLD(0.0L) || dp == CLD(0.0L)) break;
    CLD step = p / dp;
    if (std::abs(step) <= std::numeric_limits<LD>::epsilon() * std::abs(z)) break;  // converged
    bool improved = false;
    for (int half = 0; half < 60 && !improved; ++half, step /= 2.0L) {
      improved = std::abs(horner<CLD>(c, z - step)) < std::abs(p);
      if (improved) z -= step;
    }
    if (!improved) break;
  }
  return z;
}

// The m members of `roots` nearest to z.
std::vector<CLD> nearest(std::vector<CLD> roots, CLD z, int m) {
  std::sort(roots.begin(), roots.end(),
            [&](const CLD& a, const CLD& b) { return std::abs(a - z) < std::abs(b - z); });
  roots.resize(static_cast<std::size_t>(m));
  return roots;
}

// A point where the double polynomial has, or may have, real roots: a distinct real root of the
// construction with its multiplicity m, or a complex pair so close to the axis that it is within
// rounding of a real double root (`required` false: reporting it or not are both right). The
// reference is the centroid of the m companion eigenvalues nearest to it (a cluster's centroid
// is well conditioned where its members are not; simple roots are polished).
struct RealRoot {
  LD construction;
  int multiplicity;
  bool required;
  LD reference;
  LD tolerance;
};

std::vector<RealRoot> real_reference(const Quartic& c, const std::array<CLD, 4>& construction) {
  const std::vector<CLD> direct = companion_roots(c, false);
  const std::vector<CLD> reversed = companion_roots(c, true);
  std::vector<RealRoot> out;
  std::array<bool, 4> done{};
  for (std::size_t i = 0; i < 4; ++i) {
    if (done[i]) continue;
    const CLD z = construction[i];
    int m = 0;
    for (std::size_t j = i; j < 4; ++j) {
      if (construction[j] == z || construction[j] == std::conj(z)) {
        done[j] = true;
        ++m;
      }
    }
    const bool real = z.imag() == 0.0L;
    if (!real && std::fabs(z.imag()) > root_tolerance(c, z.real(), m)) continue;
    LD r = 0.0L;
    if (m == 1) {
      // Of the two nearest companion roots, polished, the one nearer to the construction.
      CLD best = polish(c, nearest(direct, z, 1)[0]);
      const CLD other = polish(c, nearest(reversed, z, 1)[0]);
      if (std::abs(other - z) < std::abs(best - z)) best = other;
      r = best.real();
    } else {
      CLD centroid = 0.0L;
      for (const CLD& e : nearest(std::abs(z) >= 1.0L ? direct : reversed, z, m)) centroid += e;
      r = (centroid / static_cast<LD>(m)).real();
    }
    out.push_back({z.real(), m, real, r, root_tolerance(c, r, m)});
  }
  std::sort(out.begin(), out.end(),
            [](const RealRoot& a, const RealRoot& b) { return a.reference < b.reference; });
  return out;
}

TEST(FirstRootReference, HardCasesOfTheLiterature) {
  // Worst error of a reported root against the reference (absolute, relative), the largest
  // relative tolerance, and the worst relative distance to the roots the case was built from.
  std::printf("%-34s %9s %9s %9s %9s\n", "case", "abs err", "rel err", "rel tol", "vs built");
  for (const HardCase& hc : hard_cases()) {
    SCOPED_TRACE(hc.name);
    const Quartic c = from_roots(hc.roots);
    const std::vector<RealRoot> ref = real_reference(c, hc.roots);
    const double bound = root_bound(c);
    const std::vector<double> found = real_roots(c, -bound, bound);
    // Every reported root lies near one reference root, and every real reference root has a
    // report: exactly one when simple; a perturbed multiple root may show as up to m.
    LD worst_abs = 0.0L;
    LD worst_rel = 0.0L;
    LD worst_tol_rel = 0.0L;
    LD worst_constr_rel = 0.0L;
    std::vector<int> reports(ref.size(), 0);
    for (double x : found) {
      std::size_t best = 0;
      for (std::size_t k = 1; k < ref.size(); ++k) {
        if (std::fabs(x - ref[k].reference) < std::fabs(x - ref[best].reference)) best = k;
      }
      ASSERT_FALSE(ref.empty()) << "reported " << x << " but there is no real root";
      const RealRoot& r = ref[best];
      const LD err = std::fabs(static_cast<LD>(x) - r.reference);
      EXPECT_LE(err, r.tolerance) << "root " << static_cast<double>(r.reference);
      EXPECT_LE(std::fabs(static_cast<LD>(x) - r.construction), r.tolerance)
          << "construction root " << static_cast<double>(r.construction);
      ++reports[best];
      worst_abs = std::max(worst_abs, err);
      worst_rel = std::max(worst_rel, err / std::fabs(r.reference));
      worst_tol_rel = std::max(worst_tol_rel, r.tolerance / std::fabs(r.reference));
      worst_constr_rel = std::max(worst_constr_rel, std::fabs(static_cast<LD>(x) - r.construction) /
                                                        std::fabs(r.construction));
    }
    for (std::size_t k = 0; k < ref.size(); ++k) {
      if (ref[k].required) {
        EXPECT_GE(reports[k], 1) << "missed root " << static_cast<double>(ref[k].reference);
      }
      EXPECT_LE(reports[k], ref[k].multiplicity) << static_cast<double>(ref[k].reference);
    }
    // The first non-positive point from the left end is the smallest real root (or a later
    // one, if all before it are optional); with no real root p > 0 throughout. -p is negative
    // at once.
    const std::optional<double> first = first_nonpositive(c, -bound, bound);
    bool first_ok = false;
    for (const RealRoot& r : ref) {
      if (first && std::fabs(static_cast<LD>(*first) - r.reference) <= r.tolerance) first_ok = true;
      if (first_ok || r.required) break;
    }
    if (!first) {
      first_ok = std::none_of(ref.begin(), ref.end(), [](const RealRoot& r) { return r.required; });
    }
    EXPECT_TRUE(first_ok) << "first non-positive point " << first.value_or(NAN);
    const Quartic neg{-c[0], -c[1], -c[2], -c[3], -c[4]};
    EXPECT_EQ(first_nonpositive(neg, -bound, bound), std::optional<double>(-bound));
    std::printf("%-34s %9.2Le %9.2Le %9.2Le %9.2Le\n", hc.name.c_str(), worst_abs, worst_rel,
                worst_tol_rel, worst_constr_rel);
  }
}

// How well roots r reproduce c: max_j |e_j - c_j / c_4| / size_j, with e the monic polynomial
// with roots r and size the same with |r_i| (the size of its coefficients' terms).
LD backward_error(const Quartic& c, const std::vector<CLD>& r) {
  std::array<CLD, 5> e{CLD(1.0L), 0.0L, 0.0L, 0.0L, 0.0L};
  std::array<LD, 5> size{1.0L, 0.0L, 0.0L, 0.0L, 0.0L};
  for (const CLD& root : r) {
    for (std::size_t k = 4; k >= 1; --k) {
      e[k] = e[k - 1] - root * e[k];
      size[k] = size[k - 1] + std::abs(root) * size[k];
    }
    e[0] = -root * e[0];
    size[0] = std::abs(root) * size[0];
  }
  LD error = 0.0L;
  for (std::size_t j = 0; j <= 4; ++j) {
    const LD ej = std::abs(e[j] - static_cast<LD>(c[j]) / static_cast<LD>(c[4])) / size[j];
    error = std::isfinite(ej) ? std::max(error, ej) : std::numeric_limits<LD>::infinity();
  }
  return error;
}

// All four roots. The companion eigenvalues, polished where that keeps them apart, when the
// eigenvalues reproduce the coefficients (backward error < 1e-8, which tells roots from
// garbage: eigenvalues that missed small roots altogether when the magnitudes differ widely).
// Else by deflation: the root of largest modulus (which the companion finds to a relative
// accuracy) is polished on the original polynomial and divided out, and the rest repeat on the
// quotient, so that roots of very different magnitudes all come out accurate.
std::vector<CLD> reference_roots(const Quartic& c) {
  const std::vector<CLD> raw = companion_roots(c, false);
  std::vector<CLD> roots = raw;
  for (std::size_t i = 0; i < 4; ++i) {
    // Polishing sharpens a simple root but can pull a member of a tight cluster onto another
    // one: keep it only where it stays nearer to its eigenvalue than half the distance to the
    // next one. (A cluster member may still move by its uncertainty, which in long double is
    // far below the double tolerance.)
    LD gap = std::numeric_limits<LD>::infinity();
    for (std::size_t j = 0; j < 4; ++j) {
      if (j != i) gap = std::min(gap, std::abs(raw[j] - raw[i]));
    }
    const CLD z = polish(c, raw[i]);
    if (std::abs(z - raw[i]) < gap / 2.0L) roots[i] = z;
  }
  if (backward_error(c, raw) < 1e-8L) return roots;
  roots.clear();
  std::vector<CLD> poly;  // ascending
  for (double x : c) poly.push_back(CLD(static_cast<LD>(x)));
  while (poly.size() > 1) {
    CLD z;
    if (poly.size() == 2) {
      z = -poly[0] / poly[1];
    } else {
      // The quotients have complex coefficients: their companion matrix by hand, for the
      // variable scaled by Fujiwara's bound B so that the largest root has modulus ~1 (the
      // eigenvalues' error is relative to the matrix's norm).
      const std::size_t n = poly.size() - 1;
      LD bound = 0.0L;
      for (std::size_t k = 0; k < n; ++k) {
        const LD ratio = std::abs(poly[k] / poly[n]) / (k == 0 ? 2.0L : 1.0L);
        bound = std::max(bound, std::pow(ratio, 1.0L / static_cast<LD>(n - k)));
      }
      bound *= 2.0L;
      const auto size = static_cast<Eigen::Index>(n);
      Eigen::Matrix<CLD, Eigen::Dynamic, Eigen::Dynamic> companion =
          Eigen::Matrix<CLD, Eigen::Dynamic, Eigen::Dynamic>::Zero(size, size);
      for (std::size_t k = 0; k < n; ++k) {
        const auto i = static_cast<Eigen::Index>(k);
        if (i > 0) companion(i, i - 1) = 1.0L;
        companion(i, size - 1) = -poly[k] / poly[n] / std::pow(bound, static_cast<LD>(n - k));
      }
      const auto eig = Eigen::ComplexEigenSolver<decltype(companion)>(companion).eigenvalues();
      z = eig[0];
      for (Eigen::Index i = 1; i < size; ++i) {
        if (std::abs(eig[i]) > std::abs(z)) z = eig[i];
      }
      z *= bound;
    }
    z = polish(c, z);
    // Eigen's cleanup for real polynomials: where the imaginary part is noise (tiny against the
    // real part), a real root within it that fits as well replaces z.
    if (std::fabs(z.imag()) <= 1e-9L * std::abs(z)) {
      const CLD real = polish(c, CLD(z.real()));
      if (std::abs(real - z) <= 2.0L * std::fabs(z.imag()) &&
          std::abs(horner<CLD>(c, real)) <= std::abs(horner<CLD>(c, z))) {
        z = real;
      }
    }
    roots.push_back(z);
    // poly / (x - z) from the constant term, b_0 = -a_0 / z, b_k = (b_(k-1) - a_k) / z: stable
    // for the root of largest modulus (Numerical Recipes, 9.5).
    std::vector<CLD> quotient(poly.size() - 1);
    for (std::size_t k = 0; k < quotient.size(); ++k) {
      quotient[k] = ((k == 0 ? CLD(0.0L) : quotient[k - 1]) - poly[k]) / z;
    }
    poly = quotient;
  }
  EXPECT_LT(backward_error(c, roots), 1e-8L) << "the reference itself";
  return roots;
}

// Random quartics against the companion reference. Each reference root z (polished) has the
// simple-root tolerance 16 eps size / |p'(z)|, which also covers a close pair or cluster: there
// p'(z) is small in proportion. A real z must have a report within it; a complex z within its
// tolerance of the axis may have one; every report must lie within tolerance of some z.
struct RandomStats {
  int polynomials = 0;
  int real_roots = 0;
  int optional_roots = 0;
  LD worst_ratio = 0.0L;  // of a report's distance to its nearest reference root to its tolerance
};

void check_against_reference(const Quartic& c, RandomStats& stats) {
  const std::vector<CLD> ref = reference_roots(c);
  std::vector<LD> tol;
  for (const CLD& z : ref) {
    tol.push_back(kTolFactor * kEps * size_at(c, std::abs(z)) / std::abs(taylor(c, z, 1)) +
                  4.0L * kEps * std::abs(z));
  }
  const double bound = root_bound(c);
  const std::vector<double> found = real_roots(c, -bound, bound);
  ++stats.polynomials;
  for (double x : found) {
    LD ratio = std::numeric_limits<LD>::infinity();
    for (std::size_t i = 0; i < 4; ++i) ratio = std::min(ratio, std::abs(CLD(x) - ref[i]) / tol[i]);
    EXPECT_LE(ratio, 1.0L) << "spurious root " << x;
    stats.worst_ratio = std::max(stats.worst_ratio, ratio);
  }
  std::optional<LD> smallest_required;
  for (std::size_t i = 0; i < 4; ++i) {
    const bool real = ref[i].imag() == 0.0L;
    if (!real && std::fabs(ref[i].imag()) > tol[i]) continue;
    (real ? stats.real_roots : stats.optional_roots) += 1;
    if (!real) continue;
    if (!smallest_required || ref[i].real() < *smallest_required) smallest_required = ref[i].real();
    const bool reported = std::any_of(found.begin(), found.end(), [&](double x) {
      return std::fabs(static_cast<LD>(x) - ref[i].real()) <= tol[i];
    });
    EXPECT_TRUE(reported) << "missed root " << static_cast<double>(ref[i].real());
  }
  // From the left end: -bound when p starts negative, else no later than the smallest real root
  // (an optional one before it may come first) and never where there is none.
  const std::optional<double> first = first_nonpositive(c, -bound, bound);
  if (c[4] < 0.0) {
    EXPECT_EQ(first, std::optional<double>(-bound));
  } else if (smallest_required) {
    ASSERT_TRUE(first.has_value());
    bool near_one = false;
    for (std::size_t i = 0; i < 4; ++i) near_one |= std::abs(CLD(*first) - ref[i]) <= tol[i];
    EXPECT_TRUE(near_one) << *first;
    std::size_t k = 0;
    for (std::size_t i = 1; i < 4; ++i) {
      if (std::fabs(ref[i].real() - *smallest_required) <
          std::fabs(ref[k].real() - *smallest_required))
        k = i;
    }
    EXPECT_LE(static_cast<LD>(*first), *smallest_required + tol[k]);
  }
}

TEST(FirstRootReference, RandomQuartics) {
  std::mt19937_64 rng(20240604);
  std::uniform_real_distribution<LD> u(-1.0L, 1.0L);
  std::normal_distribution<double> normal(0.0, 1.0);
  auto log_uniform = [&](LD lo_exp, LD hi_exp) {
    return std::pow(10.0L, lo_exp + (hi_exp - lo_exp) * (u(rng) + 1.0L) / 2.0L);
  };
  const char* names[] = {"4 real roots in [-10, 10]", "normal coefficients",
                         "clusters (3 roots within 1e-10..1e-1)", "double root + perturbation",
                         "roots of magnitude 1e-30..1e30"};
  std::printf("%-40s %7s %7s %8s %9s\n", "family", "polys", "real", "optional", "err/tol");
  for (int family = 0; family < 5; ++family) {
    RandomStats stats;
    for (int n = 0; n < 4000; ++n) {
      Quartic c{};
      std::array<CLD, 4> r{};
      switch (family) {
        case 0:
          for (CLD& x : r) x = 10.0L * u(rng);
          c = from_roots(r);
          break;
        case 1:
          for (double& x : c) x = normal(rng);
          break;
        case 2: {
          const LD base = 5.0L * u(rng);
          r = {re(base), re(base + log_uniform(-10, -1) * u(rng)),
               re(base + log_uniform(-10, -1) * u(rng)), re(5.0L * u(rng))};
          c = from_roots(r);
          break;
        }
        case 3: {
          // (x - a)^2 (x - b)(x - d) + e with |e| from 1e-16 to 1e-4 of the terms: a tangent
          // touch, a near miss or a close pair.
          const LD a = 3.0L * u(rng);
          r = {re(a), re(a), re(5.0L * u(rng)), CLD(5.0L * u(rng), 3.0L * std::fabs(u(rng)))};
          r[3] = u(rng) > 0.0L ? re(r[3].real()) : r[3];
          if (r[3].imag() != 0.0L) r[2] = std::conj(r[3]);
          c = from_roots(r);
          c[0] += static_cast<double>(u(rng) * log_uniform(-16, -4) * size_at(c, std::fabs(a)));
          break;
        }
        default:
          for (CLD& x : r) x = (u(rng) > 0.0L ? 1.0L : -1.0L) * log_uniform(-30, 30);
          c = from_roots(r);
          break;
      }
      SCOPED_TRACE(::testing::Message() << names[family] << " #" << n);
      check_against_reference(c, stats);
      if (::testing::Test::HasFailure()) return;
    }
    std::printf("%-40s %7d %7d %8d %9.2Le\n", names[family], stats.polynomials, stats.real_roots,
                stats.optional_roots, stats.worst_ratio);
  }
}

// ---------------------------------------------------------------------------------------------
// Ball-contact classification against brute force.
//
// The brute force works on the distance itself, f(t) = |P(t) - C| - R(t), in long double, and
// certifies its minimum over [t0, t1]: it samples f on a grid and splits a cell until either a
// sample is clearly inside (f < -tol), or the cell is clearly outside, or the cell is resolved to
// tol. A cell's minimum is at least min(f(a), f(b)) - M w^2 / 8 with M >= |f''| = |D''| <=
// |P'|^2 / D + |g| (D = |P - C|, R linear), |P'| at most its value at an end (|v + g t| is convex)
// and D at least (D(a) + D(b) - |P'| w) / 2.
//
// tol is what the quartic can resolve: its coefficients and Horner's evaluation each err by a few
// eps (S^2 + R^2), S(t) = |d| + |v| t + |g| t^2 / 2 (d = P(0) - C); p = (D - R)(D + R) with
// D + R ~ 2 R near contact; so tol = 8 eps (S(t1)^2 + R(t1)^2) / R(0), twice the sum of those
// bounds. A case is ambiguous, and excluded, when its minimum lies within 1.5 tol of 0.

struct Contact {
  BallisticPath path;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double r0 = 1.0;
  double growth = 0.0;
  double horizon = 1.0;
};

enum class Verdict { kEntry, kNoEntry, kAmbiguous };

struct Brute {
  const Contact& k;
  LD tol;
  long evaluations = 0;
  bool exhausted = false;  // gave up before settling (never expected)

  std::array<LD, 3> rel(LD t) const {  // P(t) - C
    std::array<LD, 3> q{};
    for (int i = 0; i < 3; ++i) {
      q[static_cast<std::size_t>(i)] = static_cast<LD>(k.path.p0_m[i]) -
                                       static_cast<LD>(k.centre[i]) +
                                       static_cast<LD>(k.path.v0_mps[i]) * t +
                                       0.5L * static_cast<LD>(k.path.accel_mps2[i]) * t * t;
    }
    return q;
  }
  LD distance(LD t) {
    ++evaluations;
    const auto q = rel(t);
    return std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]);
  }
  LD radius(LD t) const { return static_cast<LD>(k.r0) + static_cast<LD>(k.growth) * t; }
  LD speed(LD t) const {
    LD s = 0.0L;
    for (int i = 0; i < 3; ++i) {
      const LD w = static_cast<LD>(k.path.v0_mps[i]) + static_cast<LD>(k.path.accel_mps2[i]) * t;
      s += w * w;
    }
    return std::sqrt(s);
  }
  LD f(LD t) { return distance(t) - radius(t); }

  Verdict decide(LD t0, LD t1) {
    constexpr int kGrid = 64;
    constexpr long kBudget = 2000000;
    const LD g = static_cast<LD>(k.path.accel_mps2.norm());
    struct Cell {
      LD a, b, da, db;
    };
    std::vector<Cell> stack;
    LD prev_t = t0;
    LD prev_d = distance(t0);
    if (prev_d - radius(t0) < -tol) return Verdict::kEntry;
    for (int i = 1; i <= kGrid; ++i) {
      const LD t = t0 + (t1 - t0) * static_cast<LD>(i) / kGrid;
      const LD d = distance(t);
      if (d - radius(t) < -tol) return Verdict::kEntry;
      stack.push_back({prev_t, t, prev_d, d});
      prev_t = t;
      prev_d = d;
    }
    bool ambiguous = false;
    while (!stack.empty()) {
      if (evaluations > kBudget) {
        exhausted = true;
        return Verdict::kAmbiguous;
      }
      const Cell cell = stack.back();
      stack.pop_back();
      const LD w = cell.b - cell.a;
      const LD lowest = std::min(cell.da - radius(cell.a), cell.db - radius(cell.b));
      const LD v = std::max(speed(cell.a), speed(cell.b));
      const LD d_min = (cell.da + cell.db - v * w) / 2.0L;
      if (d_min > 0.0L) {
        const LD sag = (v * v / d_min + g) * w * w / 8.0L;
        if (lowest - sag > tol) continue;  // clearly outside on this cell
        if (sag <= tol / 2.0L) {           // resolved: the minimum here is within 1.5 tol of 0
          ambiguous = true;
          continue;
        }
      }
      const LD m = (cell.a + cell.b) / 2.0L;
      const LD dm = distance(m);
      if (dm - radius(m) < -tol) return Verdict::kEntry;
      stack.push_back({cell.a, m, cell.da, dm});
      stack.push_back({m, cell.b, dm, cell.db});
    }
    return ambiguous ? Verdict::kAmbiguous : Verdict::kNoEntry;
  }
};

LD resolution(const Contact& k) {
  const LD t = k.horizon;
  const LD s = (k.path.p0_m - k.centre).norm() + k.path.v0_mps.norm() * t +
               0.5L * k.path.accel_mps2.norm() * t * t;
  const LD r = k.r0 + k.growth * t;
  return 8.0L * kEps * (s * s + r * r) / k.r0;
}

struct ClassStats {
  int cases = 0;
  int agreements = 0;
  int excluded = 0;
  int entries = 0;
  LD max_tol = 0.0L;
};

void classify(const Contact& k, ClassStats& stats) {
  const Quartic q = ball_contact_quartic(k.path, k.centre, k.r0, k.growth);
  const std::optional<double> t = first_nonpositive(q, 0.0, k.horizon);
  Brute brute{k, resolution(k)};
  const Verdict v = brute.decide(0.0L, k.horizon);
  ++stats.cases;
  stats.max_tol = std::max(stats.max_tol, brute.tol);
  EXPECT_FALSE(brute.exhausted);
  if (v == Verdict::kAmbiguous) {
    ++stats.excluded;
    return;
  }
  const bool entry = v == Verdict::kEntry;
  EXPECT_EQ(t.has_value(), entry) << "p0 " << k.path.p0_m.transpose() << " v "
                                  << k.path.v0_mps.transpose() << " g "
                                  << k.path.accel_mps2.transpose() << " C " << k.centre.transpose()
                                  << " r0 " << k.r0 << " growth " << k.growth << " tG "
                                  << k.horizon;
  if (t.has_value() != entry) return;
  ++stats.agreements;
  if (!entry) return;
  ++stats.entries;
  // t_C is the first entry: inside (to tolerance) at t_C and not clearly inside before it.
  EXPECT_LE(brute.f(*t), 1.5L * brute.tol) << "t_C " << *t;
  if (*t > 0.0) {
    Brute before{k, brute.tol};
    EXPECT_NE(before.decide(0.0L, *t), Verdict::kEntry) << "entered before t_C " << *t;
  }
}

Eigen::Vector3d random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::Vector3d n(normal(rng), normal(rng), normal(rng));
  return n.normalized();
}

TEST(FirstRootReference, BallContactMatchesBruteForce) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> normal(0.0, 1.0);
  auto log_uniform = [&](double lo_exp, double hi_exp) {
    return std::pow(10.0, lo_exp + (hi_exp - lo_exp) * u(rng));
  };
  auto random_contact = [&]() {
    Contact k;
    k.centre = Eigen::Vector3d(20.0 * normal(rng), 2.0 * normal(rng), 20.0 * normal(rng));
    k.path.p0_m = k.centre + log_uniform(-2, 2) * random_unit(rng);
    k.path.v0_mps = u(rng) < 0.05 ? Eigen::Vector3d(Eigen::Vector3d::Zero())
                                  : Eigen::Vector3d(log_uniform(-1, 1.6) * random_unit(rng));
    const double gravity = u(rng);
    if (gravity < 0.5) {
      k.path.accel_mps2 = Eigen::Vector3d(0.0, -9.81, 0.0);
    } else if (gravity < 0.8) {
      k.path.accel_mps2 = 20.0 * u(rng) * random_unit(rng);
    }
    k.r0 = log_uniform(-1.7, 1);
    k.growth = u(rng) < 0.5 ? 0.0 : 10.0 * u(rng);
    k.horizon = log_uniform(-2, 1);
    return k;
  };
  const char* names[] = {"random paths", "grazing: f'(t*) = 0, f(t*) = +-1e-13..1e-1 m",
                         "starting on the sphere +-1e-13..1e-1 m",
                         "reaching it at t_G +-1e-13..1e-1 m"};
  std::printf("%-46s %6s %6s %6s %6s %9s\n", "family", "cases", "agree", "excl", "entries",
              "max tol");
  for (int family = 0; family < 4; ++family) {
    ClassStats stats;
    const int count = family == 0 ? 20000 : 5000;
    for (int n = 0; n < count; ++n) {
      Contact k = random_contact();
      const double delta = (u(rng) < 0.5 ? -1.0 : 1.0) * log_uniform(-13, -1);
      if (family == 1) {
        // A point t* where the distance is stationary relative to the growing radius, at
        // distance R(t*) + delta: P(t*) - C = rho dir with dir . P'(t*) = growth makes D'(t*) = R'.
        const double ts = k.horizon * u(rng);
        const Eigen::Vector3d vel = k.path.v0_mps + k.path.accel_mps2 * ts;
        if (vel.norm() <= k.growth) continue;
        const Eigen::Vector3d along = vel.normalized();
        Eigen::Vector3d side = random_unit(rng);
        side = (side - side.dot(along) * along).normalized();
        const double a = k.growth / vel.norm();
        const Eigen::Vector3d dir = a * along + std::sqrt(1.0 - a * a) * side;
        k.centre = k.path.at(ts) - (k.r0 + k.growth * ts + delta) * dir;
      } else if (family == 2) {
        k.centre = k.path.p0_m - (k.r0 + delta) * random_unit(rng);
      } else if (family == 3) {
        k.centre = k.path.at(k.horizon) - (k.r0 + k.growth * k.horizon + delta) * random_unit(rng);
      }
      SCOPED_TRACE(::testing::Message() << names[family] << " #" << n);
      classify(k, stats);
      if (::testing::Test::HasFailure()) return;
    }
    std::printf("%-46s %6d %6d %6d %6d %9.2Le\n", names[family], stats.cases, stats.agreements,
                stats.excluded, stats.entries, stats.max_tol);
    EXPECT_EQ(stats.agreements + stats.excluded, stats.cases);
  }
}

}  // namespace
}  // namespace fragsim
