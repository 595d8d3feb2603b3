#include "control/geometry/first_root.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <new>
#include <span>
#include <tuple>
#include <vector>

#include "control/geometry/work_space.hpp"
#include "control/memory/memory_resource.hpp"

namespace fragsim {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

constexpr double kZeroTolerance = kRootZeroTolerance;

// A cap on the bracketed search. Each step either halves the bracket or is a Newton step under half
// the one before; bisection alone reaches adjacent doubles in ~64 halvings (see `split`), and ~5
// steps are typical.
constexpr int kMaxIterations = 160;

// Room for one level's roots or break points; a quartic needs at most 4 and 5.
constexpr std::size_t kCapacity = 8;
using Points = std::array<double, kCapacity>;

double at(const Quartic& c, int k) {
  return c[static_cast<std::size_t>(k)];
}

int degree(const Quartic& c) {
  for (int d = 4; d > 0; --d) {
    if (at(c, d) != 0.0) return d;
  }
  return 0;
}

Quartic derivative(const Quartic& c) {
  return {c[1], 2.0 * c[2], 3.0 * c[3], 4.0 * c[4], 0.0};
}

// p(x), p'(x) and the size of the terms, sum |c_k| |x|^k, all divided by one positive factor (1, or
// |x|^D where Horner's form would overflow). Signs, the Newton step p / p' and the ratio |p| / size
// that judges "zero" are the same either way.
struct Sample {
  double p;
  double dp;
  double size;
};

// From the reversed polynomial q(u) = p(x) / x^D, u = 1 / x, whose Horner form multiplies by
// |u| <= 1 where |x| >= 1, for roots or intervals near the top of the double range.
template <int D>
Sample sample_reversed(const Quartic& c, double x) {
  const double u = 1.0 / x;
  const double au = std::abs(u);
  double q = c[0];
  double dq = 0.0;
  double size = std::abs(c[0]);
  for (int k = 1; k <= D; ++k) {
    dq = dq * u + q;
    q = q * u + at(c, k);
    size = size * au + std::abs(at(c, k));
  }
  // p'(x) = x^(D-1) (D q - u q'(u)), which divided by x^D is u (D q - u q').
  double dp = u * (D * q - u * dq);
  if (D % 2 == 1 && x < 0.0) {  // x^D < 0, so divide by |x|^D instead
    q = -q;
    dp = -dp;
  }
  return {q, dp, size};
}

// Inlined, as it is called two to three times per quadratic's roots, and a call costs as much as
// its few operations (-ffp-contract=off keeps the rounding the same either way).
template <int D>
[[gnu::always_inline]] inline Sample sample(const Quartic& c, double x) {
  const double ax = std::abs(x);
  double p = at(c, D);
  double dp = 0.0;
  double size = std::abs(p);
  for (int k = D - 1; k >= 0; --k) {
    dp = dp * x + p;
    p = p * x + at(c, k);
    size = size * ax + std::abs(at(c, k));
  }
  // An overflow anywhere in the recurrences leaves an inf or a NaN in one of these.
  if (std::isfinite(size) && std::isfinite(dp)) return {p, dp, size};
  return sample_reversed<D>(c, x);
}

bool near_zero(const Sample& s) {
  return std::abs(s.p) <= kZeroTolerance * s.size;
}

// std::bit_cast, which emscripten's libc++ 14 lacks.
template <class To, class From>
To bits_as(const From& from) {
  static_assert(sizeof(To) == sizeof(From));
  To to;
  std::memcpy(&to, &from, sizeof(To));
  return to;
}

// A point strictly inside (a, b) when there is one, else a or b. The arithmetic midpoint when the
// ends have one sign and lie within a factor 1024; otherwise 0 or the midpoint of the bit patterns
// (a geometric mean), so a bracket spanning many binades still shrinks to adjacent doubles in about
// 64 halvings.
double split(double a, double b) {
  if (a < 0.0 && b > 0.0) return 0.0;
  const double small = std::min(std::abs(a), std::abs(b));
  const double large = std::max(std::abs(a), std::abs(b));
  if (large <= 1024.0 * small) return a + 0.5 * (b - a);
  const auto is = bits_as<std::uint64_t>(small);
  const auto il = bits_as<std::uint64_t>(large);
  const double mid = bits_as<double>(is + (il - is) / 2);
  return b > 0.0 ? mid : -mid;
}

// The root of p between a < b, given p(a) = fa and p(b) = fb of strictly opposite signs. Newton's
// method from the regula falsi point, keeping the bracket; a step that would leave the bracket, or
// is not under half the step before, is replaced by halving the bracket (the safeguard of Numerical
// Recipes' rtsafe, section 9.4). Ends when the Newton step is below an ulp or the bracket is two
// adjacent doubles, as close to the computed p's sign change as bisection gets. One search as a
// state advanced an iteration at a time, so many of them can be advanced in turn
// (solve_bracketed_many), and each search does the same operations either way.
template <int D>
struct BracketedSearch {
  const Quartic* c = nullptr;
  double neg = 0.0;  // computed p < 0 here
  double pos = 0.0;  // computed p > 0 here
  double x = 0.0;
  double step = 0.0;
  int iteration = 0;

  BracketedSearch() = default;
  BracketedSearch(const Quartic& poly, double a, double b, double fa, double fb)
      : c(&poly), neg(fa < 0.0 ? a : b), pos(fa < 0.0 ? b : a), step(b - a) {
    x = a - fa * ((b - a) / (fb - fa));
    if (!(x > a && x < b)) x = split(a, b);
  }

  // One iteration; true when the search has ended, its root then in x.
  bool advance() {
    if (iteration == kMaxIterations) return true;
    ++iteration;
    const Sample s = sample<D>(*c, x);
    if (s.p == 0.0) return true;
    (s.p < 0.0 ? neg : pos) = x;
    const double lo = std::min(neg, pos);
    const double hi = std::max(neg, pos);
    const double newton = x - s.p / s.dp;
    const double newton_step = std::abs(newton - x);
    const double step_before = step;
    if (newton > lo && newton < hi && newton_step < 0.5 * step_before) {
      x = newton;
      if (newton_step <= kEps * std::abs(newton)) return true;
      step = newton_step;
    } else {
      const double m = split(lo, hi);
      if (!(m > lo && m < hi)) return true;
      step = hi - lo;
      x = m;
    }
    return false;
  }
};

template <int D>
double solve_bracketed(const Quartic& c, double a, double b, double fa, double fb) {
  BracketedSearch<D> search(c, a, b, fa, fb);
  while (!search.advance()) {
  }
  return search.x;
}

// Every search to its end, advanced in turn. One search's iteration is a chain of dependent
// operations (Horner's rule, a division), so taking several chains in turn lets the processor
// overlap them, where one search alone waits on each.
template <int D>
void solve_bracketed_many(std::span<BracketedSearch<D>> searches) {
  std::size_t live = searches.size();
  std::array<std::size_t, 64> order{};
  for (std::size_t begin = 0; begin < searches.size(); begin += order.size()) {
    const std::size_t end = std::min(searches.size(), begin + order.size());
    live = 0;
    for (std::size_t j = begin; j < end; ++j) order[live++] = j;
    while (live > 0) {
      std::size_t kept = 0;
      for (std::size_t k = 0; k < live; ++k) {
        if (!searches[order[k]].advance()) order[kept++] = order[k];
      }
      live = kept;
    }
  }
}

template <int D>
std::size_t real_roots_of(const Quartic& c, double lo, double hi, Points& out);

// The root of a quadratic between a < b where p(a) = fa and p(b) = fb have strictly opposite signs
// (p monotone between, so the exact p has one root there), by the stable closed form, about a third
// of the bracketed search's cost (a square root and two divisions against ~5 Newton iterations of
// Horner's rule). Its error is a few ulps of the root plus the discriminant's rounding, the same
// order as the search's stopping rule (docs/benchmarks.md, "The worst frame"). Where rounding puts
// neither closed-form root inside [a, b] (a discriminant lost to cancellation, coefficients near
// the ends of the double range), the search decides.
double quadratic_root_between(const Quartic& q, double a, double b, double fa, double fb) {
  const double c2 = q[2];
  const double c1 = q[1];
  const double c0 = q[0];
  const double disc = c1 * c1 - 4.0 * c2 * c0;
  if (std::isfinite(disc) && disc >= 0.0) {
    const double h = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
    if (h != 0.0) {
      const double r1 = h / c2;
      const double r2 = c0 / h;
      if (r1 >= a && r1 <= b) return r1;
      if (r2 >= a && r2 <= b) return r2;
    }
  }
  return solve_bracketed<2>(q, a, b, fa, fb);
}

// The crossing of p between two break points (closed form for a quadratic, else the search).
template <int D>
double root_between(const Quartic& c, double a, double b, double fa, double fb) {
  if constexpr (D == 2) {
    return quadratic_root_between(c, a, b, fa, fb);
  } else {
    return solve_bracketed<D>(c, a, b, fa, fb);
  }
}

// The roots of a x^2 + b x + c (a != 0) strictly inside (lo, hi), ascending, for use as break
// points. It uses the stable formula, and where rounding makes the discriminant negative the vertex
// stands in for two close roots (an extra break point is harmless, a missing one is not). Returns
// nothing where the formula could over- or underflow; the caller then searches instead.
std::optional<std::size_t> quadratic_break_points(const Quartic& q, double lo, double hi,
                                                  Points& out) {
  const double a = q[2];
  const double b = q[1];
  const double c = q[0];
  const double disc = b * b - 4.0 * a * c;
  if (!std::isfinite(disc) || std::max({std::abs(a), std::abs(b), std::abs(c)}) < 1e-100) {
    return std::nullopt;
  }
  std::array<double, 2> r{};
  std::size_t n = 0;
  if (disc < 0.0) {
    r[n++] = -b / (2.0 * a);
  } else {
    const double h = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    const double r1 = h / a;
    const double r2 = h != 0.0 ? c / h : r1;
    r[n++] = std::min(r1, r2);
    r[n++] = std::max(r1, r2);
  }
  std::size_t count = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (r[i] > lo && r[i] < hi) out[count++] = r[i];
  }
  return count;
}

// lo, the roots of p' strictly inside (lo, hi) ascending, then hi, so p is monotone between
// consecutive points (up to rounding, where p' is itself within rounding of zero).
template <int D>
std::size_t break_points(const Quartic& c, double lo, double hi, Points& pts) {
  std::size_t n = 0;
  pts[n++] = lo;
  if constexpr (D >= 2) {
    const Quartic dc = derivative(c);
    Points crit;
    std::optional<std::size_t> m;
    if constexpr (D == 3) m = quadratic_break_points(dc, lo, hi, crit);
    if (!m) m = real_roots_of<D - 1>(dc, lo, hi, crit);
    for (std::size_t i = 0; i < *m; ++i) {
      if (crit[i] > pts[n - 1] && crit[i] < hi && n + 1 < kCapacity) pts[n++] = crit[i];
    }
  }
  pts[n++] = hi;
  return n;
}

template <int D>
std::size_t real_roots_of(const Quartic& c, double lo, double hi, Points& out) {
  std::size_t count = 0;
  auto add = [&](double r) {
    if (count < kCapacity && (count == 0 || r > out[count - 1])) out[count++] = r;
  };
  if constexpr (D == 1) {
    const double r = -c[0] / c[1];
    if (r >= lo && r <= hi) add(r);
  } else {
    Points pts;
    const std::size_t n = break_points<D>(c, lo, hi, pts);
    Sample sa = sample<D>(c, pts[0]);
    bool za = near_zero(sa);
    // A break point where p vanishes to rounding is a root; a double root is found here.
    if (za) add(pts[0]);
    for (std::size_t i = 0; i + 1 < n; ++i) {
      const Sample sb = sample<D>(c, pts[i + 1]);
      const bool zb = near_zero(sb);
      if (!za && !zb && (sa.p < 0.0) != (sb.p < 0.0)) {
        add(root_between<D>(c, pts[i], pts[i + 1], sa.p, sb.p));
      }
      if (zb) add(pts[i + 1]);
      sa = sb;
      za = zb;
    }
  }
  return count;
}

// True when p > 0 on [lo, hi] with a margin beyond the zero judgement, certified by p's Bernstein
// coefficients on [lo, hi] (p lies in their convex hull). One pass of ~40 flops settles most paths
// that stay clear of the ball. With size = sum |c_k| (|lo| + hi - lo)^k, which bounds the terms
// anywhere in the interval, the margin 32 eps size covers the conversion's rounding
// (< 16 eps size), the zero tolerance and Horner's error (8 eps size), so when this says "positive"
// the full search would too.
template <int D>
bool clearly_positive(const Quartic& c, double lo, double hi) {
  // Taylor shift to lo and scale to [0, 1], so a_k = p^(k)(lo) h^k / k!.
  std::array<double, D + 1> a;
  for (int k = 0; k <= D; ++k) a[static_cast<std::size_t>(k)] = at(c, k);
  if (lo != 0.0) {
    for (std::size_t i = 0; i < D; ++i) {
      for (std::size_t k = D; k-- > i;) a[k] += lo * a[k + 1];
    }
  }
  const double h = hi - lo;
  double hk = 1.0;
  for (std::size_t k = 1; k <= D; ++k) {
    hk *= h;
    a[k] *= hk;
  }
  // h^k out of the normal range (overflow to inf, or underflow that silently drops the high-order
  // terms) makes the certificate meaningless, so the full search decides (found by fuzzing).
  if (!std::isfinite(hk) || (h > 0.0 && hk < std::numeric_limits<double>::min())) return false;
  for (double v : a) {
    if (!std::isfinite(v)) return false;
  }
  const double reach = std::abs(lo) + h;
  double size = 0.0;
  for (int k = D; k >= 0; --k) size = size * reach + std::abs(at(c, k));
  if (!std::isfinite(size)) return false;
  const double margin = 32.0 * kEps * size;
  // b_i = sum_k C(i, k) / C(D, k) a_k.
  for (std::size_t i = 0; i <= D; ++i) {
    double b = 0.0;
    double w = 1.0;
    for (std::size_t k = 0; k <= i; ++k) {
      b += w * a[k];
      w *= static_cast<double>(i - k) / static_cast<double>(D - k);
    }
    if (!(b > margin) || !std::isfinite(b)) return false;
  }
  return true;
}

template <int D>
std::optional<double> first_nonpositive_of(const Quartic& c, double lo, double hi) {
  Sample prev = sample<D>(c, lo);
  if (prev.p <= 0.0 || near_zero(prev)) return lo;
  if (clearly_positive<D>(c, lo, hi)) return std::nullopt;
  Points pts;
  const std::size_t n = break_points<D>(c, lo, hi, pts);
  for (std::size_t i = 1; i < n; ++i) {
    const Sample s = sample<D>(c, pts[i]);
    // A break point within rounding of zero is a touch (a double root at a critical point). It is
    // exact there, while a root search would stop up to sqrt(eps) early, where rounding first makes
    // p look non-positive.
    if (near_zero(s)) return pts[i];
    // p > 0 at the previous point, < 0 here, monotone between, so one crossing.
    if (s.p < 0.0) return root_between<D>(c, pts[i - 1], pts[i], prev.p, s.p);
    prev = s;
  }
  return std::nullopt;
}

// A bracket [a, b] of a quartic's first crossing near a guess (first_nonpositive_near), given
// p(lo) > 0 beyond rounding, with p certified positive on [lo, a], p(a) > 0 > p(b) beyond rounding,
// and p' certified negative on [a, b], so the first crossing is the one in [a, b].
struct Bracket {
  double a, b, fa, fb;
};
std::optional<Bracket> bracket_near(const Quartic& c, double lo, double hi, double guess,
                                    double half_width) {
  if (!(std::isfinite(guess) && half_width > 0.0)) return std::nullopt;
  const double a = std::max(lo, guess - half_width);
  const double b = std::min(hi, guess + half_width);
  if (!(a < b)) return std::nullopt;
  if (a > lo && !clearly_positive<4>(c, lo, a)) return std::nullopt;
  const Sample sa = sample<4>(c, a);
  if (!(sa.p > 0.0) || near_zero(sa)) return std::nullopt;
  const Sample sb = sample<4>(c, b);
  if (!(sb.p < 0.0) || near_zero(sb)) return std::nullopt;
  const Quartic d = derivative(c);
  if (!clearly_positive<3>({-d[0], -d[1], -d[2], -d[3], 0.0}, a, b)) return std::nullopt;
  return Bracket{a, b, sa.p, sb.p};
}

bool usable(const Quartic& c, double lo, double hi) {
  // x - x is 0 for a finite x and NaN for an infinite or NaN one, so the sum is 0 only when every
  // number is finite (one test instead of seven).
  const double sum = (lo - lo) + (hi - hi) + (c[0] - c[0]) + (c[1] - c[1]) + (c[2] - c[2]) +
                     (c[3] - c[3]) + (c[4] - c[4]);
  return lo <= hi && sum == 0.0;
}

}  // namespace

double evaluate(const Quartic& c, double x) {
  return c[0] + x * (c[1] + x * (c[2] + x * (c[3] + x * c[4])));
}

std::optional<double> first_nonpositive_near(const Quartic& c, double lo, double hi, double guess,
                                             double half_width) {
  if (usable(c, lo, hi) && degree(c) == 4) {
    const Sample first = sample<4>(c, lo);
    if (first.p > 0.0 && !near_zero(first)) {
      if (const std::optional<Bracket> br = bracket_near(c, lo, hi, guess, half_width)) {
        return solve_bracketed<4>(c, br->a, br->b, br->fa, br->fb);
      }
    }
  }
  return first_nonpositive(c, lo, hi);
}

std::vector<double> real_roots(const Quartic& c, double lo, double hi) {
  const RootList r = list_real_roots(c, lo, hi);
  return {r.begin(), r.end()};
}

RootList list_real_roots(const Quartic& c, double lo, double hi) {
  static_assert(std::tuple_size_v<decltype(RootList::x)> == kCapacity);
  RootList r;
  if (!usable(c, lo, hi)) return r;
  switch (degree(c)) {
    case 1:
      r.n = real_roots_of<1>(c, lo, hi, r.x);
      break;
    case 2:
      r.n = real_roots_of<2>(c, lo, hi, r.x);
      break;
    case 3:
      r.n = real_roots_of<3>(c, lo, hi, r.x);
      break;
    case 4:
      r.n = real_roots_of<4>(c, lo, hi, r.x);
      break;
    default:
      break;  // a constant has no isolated roots (all or none)
  }
  return r;
}

std::optional<double> first_nonpositive(const Quartic& c, double lo, double hi) {
  if (!usable(c, lo, hi)) return std::nullopt;
  switch (degree(c)) {
    case 1:
      return first_nonpositive_of<1>(c, lo, hi);
    case 2:
      return first_nonpositive_of<2>(c, lo, hi);
    case 3:
      return first_nonpositive_of<3>(c, lo, hi);
    case 4:
      return first_nonpositive_of<4>(c, lo, hi);
    default:
      return c[0] <= 0.0 ? std::optional<double>(lo) : std::nullopt;
  }
}

// FirstNonpositiveBatch is first_nonpositive_of<4> cut where it waits on a root search. Per
// polynomial, first the derivative's roots as real_roots_of<3> finds them (its break points and
// samples, each sign change a search to run, each near-zero sample a root as it is), then, with
// every one of those searches done, the break points of the quartic and its first sign change (a
// search), then those searches. Other degrees (no gravity) go through first_nonpositive.
struct FirstNonpositiveBatch::Work {
  // Where a quartic stands between the stages.
  enum class State { kDone, kCritical, kCrossing };
  struct Entry {
    double value = 0.0;  // a root as it is, when search < 0
    int search = -1;     // else the cubic search that finds it
  };
  struct Pending {
    State state = State::kDone;
    std::array<Entry, 2 * kCapacity> entries{};
    std::size_t entry_count = 0;
    int crossing = -1;  // the quartic search
  };
  explicit Work(MemoryResource* m) : mem(m) {}
  Work(const Work&) = delete;
  // The contents only, as each keeps its own resource.
  void copy_from(const Work& o) {
    out = o.out;
    pending = o.pending;
    cubic_searches = o.cubic_searches;
    quartic_searches = o.quartic_searches;
    derivatives = o.derivatives;
  }
  MemoryResource* const mem;
  ResourceVector<std::optional<double>> out{mem};
  ResourceVector<Pending> pending{mem};
  ResourceVector<BracketedSearch<3>> cubic_searches{mem};
  ResourceVector<BracketedSearch<4>> quartic_searches{mem};
  ResourceVector<Quartic> derivatives{mem};

  // A Work allocated from mem, as everything it holds.
  static Work* make(MemoryResource* mem) {
    void* p = mem->allocate(sizeof(Work), alignof(Work));
    return new (p) Work(mem);  // cannot throw, as the vectors start empty
  }
};

void FirstNonpositiveBatch::Release::operator()(Work* w) const {
  MemoryResource* mem = w->mem;
  w->~Work();
  mem->deallocate(w, sizeof(Work), alignof(Work));
}

FirstNonpositiveBatch::FirstNonpositiveBatch(MemoryResource* mem) : work_(Work::make(mem)) {}
FirstNonpositiveBatch::~FirstNonpositiveBatch() = default;

void FirstNonpositiveBatch::reserve(std::size_t n) {
  reserve_touched(work_->out, n);
  reserve_touched(work_->pending, n);
  reserve_touched(work_->derivatives, n);
  // A quartic brackets its first crossing between at most three critical points.
  reserve_touched(work_->cubic_searches, 3 * n);
  reserve_touched(work_->quartic_searches, n);
}
FirstNonpositiveBatch::FirstNonpositiveBatch(const FirstNonpositiveBatch& other)
    : work_(Work::make(other.work_->mem)) {
  work_->copy_from(*other.work_);
}
FirstNonpositiveBatch& FirstNonpositiveBatch::operator=(const FirstNonpositiveBatch& other) {
  if (this != &other) work_->copy_from(*other.work_);
  return *this;
}

std::span<const std::optional<double>> FirstNonpositiveBatch::run(std::span<const Quartic> c,
                                                                  double lo,
                                                                  std::span<const double> hi) {
  return run(c, lo, hi, {}, 0.0);
}

std::span<const std::optional<double>> FirstNonpositiveBatch::run(std::span<const Quartic> c,
                                                                  double lo,
                                                                  std::span<const double> hi,
                                                                  std::span<const double> guess,
                                                                  double half_width) {
  Work& w = *work_;
  const std::size_t n = c.size();
  w.out.assign(n, std::nullopt);
  w.pending.resize(n);
  w.derivatives.resize(n);
  w.cubic_searches.clear();
  w.quartic_searches.clear();
  // Stage 1: what first_nonpositive_of<4> does before break_points<4>, then real_roots_of<3> on
  // the derivative up to its searches.
  for (std::size_t j = 0; j < n; ++j) {
    Work::Pending& pj = w.pending[j];
    pj.state = Work::State::kDone;
    pj.entry_count = 0;
    if (!usable(c[j], lo, hi[j]) || degree(c[j]) != 4) {
      w.out[j] = first_nonpositive(c[j], lo, hi[j]);
      continue;
    }
    const Sample first = sample<4>(c[j], lo);
    if (first.p <= 0.0 || near_zero(first)) {
      w.out[j] = lo;
      continue;
    }
    if (clearly_positive<4>(c[j], lo, hi[j])) continue;
    // A guess that brackets the crossing skips the derivative's roots, straight to the search.
    if (!guess.empty()) {
      if (const std::optional<Bracket> br = bracket_near(c[j], lo, hi[j], guess[j], half_width)) {
        pj.state = Work::State::kCrossing;
        pj.crossing = static_cast<int>(w.quartic_searches.size());
        w.quartic_searches.emplace_back(c[j], br->a, br->b, br->fa, br->fb);
        continue;
      }
    }
    w.derivatives[j] = derivative(c[j]);
    const Quartic& dc = w.derivatives[j];
    Points pts;
    const std::size_t m = break_points<3>(dc, lo, hi[j], pts);
    auto value = [&pj](double r) { pj.entries[pj.entry_count++] = {r, -1}; };
    Sample sa = sample<3>(dc, pts[0]);
    bool za = near_zero(sa);
    if (za) value(pts[0]);
    for (std::size_t i = 0; i + 1 < m; ++i) {
      const Sample sb = sample<3>(dc, pts[i + 1]);
      const bool zb = near_zero(sb);
      if (!za && !zb && (sa.p < 0.0) != (sb.p < 0.0)) {
        pj.entries[pj.entry_count++] = {0.0, static_cast<int>(w.cubic_searches.size())};
        w.cubic_searches.emplace_back(dc, pts[i], pts[i + 1], sa.p, sb.p);
      }
      if (zb) value(pts[i + 1]);
      sa = sb;
      za = zb;
    }
    pj.state = Work::State::kCritical;
  }
  solve_bracketed_many<3>(w.cubic_searches);
  // Stage 2: real_roots_of<3>'s list from its entries, break_points<4> from that, then the scan
  // of first_nonpositive_of<4> up to its search.
  for (std::size_t j = 0; j < n; ++j) {
    Work::Pending& pj = w.pending[j];
    if (pj.state != Work::State::kCritical) continue;
    pj.state = Work::State::kDone;
    Points crit;
    std::size_t count = 0;
    for (std::size_t e = 0; e < pj.entry_count; ++e) {
      const Work::Entry& entry = pj.entries[e];
      const double r = entry.search < 0
                           ? entry.value
                           : w.cubic_searches[static_cast<std::size_t>(entry.search)].x;
      if (count < kCapacity && (count == 0 || r > crit[count - 1])) crit[count++] = r;
    }
    Points pts;
    std::size_t m = 0;
    pts[m++] = lo;
    for (std::size_t i = 0; i < count; ++i) {
      if (crit[i] > pts[m - 1] && crit[i] < hi[j] && m + 1 < kCapacity) pts[m++] = crit[i];
    }
    pts[m++] = hi[j];
    Sample prev = sample<4>(c[j], lo);
    for (std::size_t i = 1; i < m; ++i) {
      const Sample s = sample<4>(c[j], pts[i]);
      if (near_zero(s)) {
        w.out[j] = pts[i];
        break;
      }
      if (s.p < 0.0) {
        pj.state = Work::State::kCrossing;
        pj.crossing = static_cast<int>(w.quartic_searches.size());
        w.quartic_searches.emplace_back(c[j], pts[i - 1], pts[i], prev.p, s.p);
        break;
      }
      prev = s;
    }
  }
  solve_bracketed_many<4>(w.quartic_searches);
  for (std::size_t j = 0; j < n; ++j) {
    if (w.pending[j].state == Work::State::kCrossing) {
      w.out[j] = w.quartic_searches[static_cast<std::size_t>(w.pending[j].crossing)].x;
    }
  }
  return w.out;
}

}  // namespace fragsim
