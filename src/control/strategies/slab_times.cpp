#include "control/strategies/slab_times.hpp"

#include <array>
#include <cstddef>
#include <cstring>

#include "control/geometry/first_root.hpp"
#include "control/strategies/lane_ops.hpp"

namespace fragsim {
namespace {

// first_root.cpp's sample<2> and near_zero in lanes, p(x) by Horner's rule and the size of its
// terms, in the same operations. `finite` is clear in a lane where the size or p' overflowed, where
// list_real_roots samples the reversed polynomial instead.
template <class O>
struct SampleOf {
  typename O::V p;
  typename O::M finite;
  typename O::M zero;  // |p| within rounding of zero
};
template <class O, class V = typename O::V>
[[gnu::always_inline]] inline SampleOf<O> sample(const V (&q)[3], V x) {
  const V ax = O::abs(x);
  V p = q[2];
  V dp = O::splat(0.0);
  V size = O::abs(p);
  dp = dp * x + p;
  p = p * x + q[1];
  size = size * ax + O::abs(q[1]);
  dp = dp * x + p;
  p = p * x + q[0];
  size = size * ax + O::abs(q[0]);
  const V zero = O::splat(0.0);
  return {p, O::eq(size - size, zero) & O::eq(dp - dp, zero),
          O::le(O::abs(p), O::splat(kRootZeroTolerance) * size)};
}

// Each lane's roots in [lo, hi] of c0 + c1 t + c2 t^2, as list_real_roots lists them, where they
// come from its common branches, a linear lane's one root, or a quadratic lane's crossings, one per
// piece between its break points (lo, the vertex where strictly inside, hi) whose ends have
// strictly opposite signs, each the closed form's r1 or r2, whichever lies in the piece
// (real_roots_of<2>, quadratic_root_between). `slow` marks the lanes that need list_real_roots
// itself, for a sample that overflowed, a break point within rounding of zero (a root there), or a
// crossing the closed form cannot place (the bracketed search decides it).
template <class O>
struct LaneRootsOf {
  typename O::V first;
  typename O::V second;
  typename O::M one;   // at least one root
  typename O::M two;   // two roots
  typename O::M slow;  // ask list_real_roots
};
template <class O, class V = typename O::V, class M = typename O::M>
[[gnu::always_inline]] inline LaneRootsOf<O> lane_roots(const V (&q)[3], V lo, V hi) {
  const V zero = O::splat(0.0);
  // As list_real_roots' usable(), the interval is ordered and every number finite (x - x is 0 only
  // for a finite x).
  const V finite = (lo - lo) + (hi - hi) + (q[0] - q[0]) + (q[1] - q[1]) + (q[2] - q[2]);
  const M usable = O::le(lo, hi) & O::eq(finite, zero);
  const M quadratic = usable & O::ne(q[2], zero);
  const M linear = usable & O::none_of(O::ne(q[2], zero)) & O::ne(q[1], zero);
  // Degree 1's root is -c0 / c1 (real_roots_of<1>), degree 2's vertex the root of the derivative
  // c1 + 2 c2 t (real_roots_of<1> on it). Lanes of the other degree divide by zero here, unread.
  const V line_root = -q[0] / q[1];
  const M line_in = O::ge(line_root, lo) & O::le(line_root, hi);
  const V vertex = -q[1] / (2.0 * q[2]);
  const M has_vertex = O::gt(vertex, lo) & O::lt(vertex, hi);
  const SampleOf<O> at_lo = sample<O>(q, lo);
  const SampleOf<O> at_vertex = sample<O>(q, vertex);
  const SampleOf<O> at_hi = sample<O>(q, hi);
  // quadratic_root_between's closed form gives the same numbers for either piece of a lane.
  const V disc = q[1] * q[1] - 4.0 * q[2] * q[0];
  const V h = -0.5 * (q[1] + O::copysign(O::sqrt(disc), q[1]));
  const M closed = O::eq(disc - disc, zero) & O::ge(disc, zero) & O::ne(h, zero);
  const V r1 = h / q[2];
  const V r2 = q[0] / h;
  const auto differ = [](M a, M b) { return (a & O::none_of(b)) | (O::none_of(a) & b); };
  // The first piece ends at the vertex where it is inside, else at hi; the second, from the
  // vertex to hi, exists only then.
  const V end1 = O::select(has_vertex, vertex, hi);
  const V end1_p = O::select(has_vertex, at_vertex.p, at_hi.p);
  const M end1_zero = (has_vertex & at_vertex.zero) | (O::none_of(has_vertex) & at_hi.zero);
  const M cross1 =
      O::none_of(at_lo.zero | end1_zero) & differ(O::lt(at_lo.p, zero), O::lt(end1_p, zero));
  const M r1_in1 = O::ge(r1, lo) & O::le(r1, end1);
  const M r2_in1 = O::ge(r2, lo) & O::le(r2, end1);
  const M cross2 = has_vertex & O::none_of(at_vertex.zero | at_hi.zero) &
                   differ(O::lt(at_vertex.p, zero), O::lt(at_hi.p, zero));
  const M r1_in2 = O::ge(r1, vertex) & O::le(r1, hi);
  const M r2_in2 = O::ge(r2, vertex) & O::le(r2, hi);
  const V root1 = O::select(r1_in1, r1, r2);
  const V root2 = O::select(r1_in2, r1, r2);
  const M sampled = at_lo.finite & at_hi.finite & (O::none_of(has_vertex) | at_vertex.finite);
  const M touches = at_lo.zero | at_hi.zero | (has_vertex & at_vertex.zero);
  const M unplaced = (cross1 & O::none_of(closed & (r1_in1 | r2_in1))) |
                     (cross2 & O::none_of(closed & (r1_in2 | r2_in2)));
  LaneRootsOf<O> out;
  out.first = O::select(linear, line_root, O::select(cross1, root1, root2));
  out.second = root2;
  out.one = (linear & line_in) | (quadratic & (cross1 | cross2));
  // A later root is listed only when it exceeds the one before (list_real_roots' add()).
  out.two = quadratic & cross1 & cross2 & O::gt(root2, root1);
  out.slow = quadratic & (O::none_of(sampled) | touches | unplaced);
  return out;
}

// Lane k's roots from lane_roots, or list_real_roots for a slow lane.
RootList lane_root_list(const LaneRootsOf<NarrowOps>& r, int k, const NarrowOps::V (&q)[3],
                        double lo, double hi) {
  if (((NarrowOps::bits(r.slow) >> k) & 1) != 0)
    return list_real_roots({q[0][k], q[1][k], q[2][k], 0.0, 0.0}, lo, hi);
  RootList list;
  list.n = static_cast<std::size_t>(((NarrowOps::bits(r.one) >> k) & 1) +
                                    ((NarrowOps::bits(r.two) >> k) & 1));
  list.x[0] = r.first[k];
  list.x[1] = r.second[k];
  return list;
}

// The rest of the definition, given both bounds' roots. t0, t1 and the roots are sorted by
// insertion (at most six points), then each piece between consecutive points is kept where its
// midpoint is inside, joined to the one before where they touch.
[[gnu::always_inline]] inline Intervals pieces_inside(const AxisQuadratic& c,
                                                      const AxisQuadratic& lo,
                                                      const AxisQuadratic& hi, double t0, double t1,
                                                      const RootList& lo_roots,
                                                      const RootList& hi_roots) {
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
  for (const RootList* r : {&lo_roots, &hi_roots}) {
    for (const double x : *r) {
      if (np < static_cast<int>(pts.size())) add(x);
    }
  }
  Intervals out;
  for (int i = 0; i + 1 < np; ++i) {
    const double a = pts[static_cast<std::size_t>(i)];
    const double b = pts[static_cast<std::size_t>(i + 1)];
    const double m = 0.5 * (a + b);
    const double mid = c.at(m);
    const bool inside = b > a ? (mid >= lo.at(m) && mid <= hi.at(m)) : false;
    if (!inside) continue;
    if (out.n > 0 && out.span[static_cast<std::size_t>(out.n - 1)][1] >= a) {
      out.span[static_cast<std::size_t>(out.n - 1)][1] = b;  // contiguous with the previous piece
    } else {
      out.append(a, b);
    }
  }
  // A path that starts inside has t0 in the set even when the first piece is degenerate.
  const double v0 = c.at(t0);
  if (out.n == 0 && v0 >= lo.at(t0) && v0 <= hi.at(t0)) out.append(t0, t0);
  return out;
}

#if defined(FRAGSIM_WIDE_LANES)
// A mask's bits by AVX's own instruction (WideOps::bits is the portable, slower form).
[[gnu::target("avx2"), gnu::always_inline]] inline int bits(const WideOps::M& m) {
  return _mm256_movemask_pd(reinterpret_cast<__m256d>(m.bits));
}

// Two slabs' bounds' roots in four lanes, a's lower and upper bound, then b's. The upper halves of
// the vector registers are cleared before returning to code compiled without AVX, as GCC 12 does
// not clear them here and the SSE code after it runs 2.5 times slower on the benchmark machine
// (docs/benchmarks.md's fourth round).
[[gnu::target("avx2")]] void bound_roots_wide(const Slab& a, const Slab& b, double t0, double t1,
                                              RootList (&out)[4]) {
  using O = WideOps;
  const O::V q[3] = {
      O::V{a.c.c0, a.c.c0, b.c.c0, b.c.c0} - O::V{a.lo.c0, a.hi.c0, b.lo.c0, b.hi.c0},
      O::V{a.c.c1, a.c.c1, b.c.c1, b.c.c1} - O::V{a.lo.c1, a.hi.c1, b.lo.c1, b.hi.c1},
      O::V{a.c.c2, a.c.c2, b.c.c2, b.c.c2} - O::V{a.lo.c2, a.hi.c2, b.lo.c2, b.hi.c2}};
  const LaneRootsOf<O> r = lane_roots<O>(q, O::splat(t0), O::splat(t1));
  const int one = bits(r.one);
  const int two = bits(r.two);
  const int slow = bits(r.slow);
  double first[4];
  double second[4];
  double coef[3][4];
  std::memcpy(first, &r.first, sizeof first);
  std::memcpy(second, &r.second, sizeof second);
  for (int i = 0; i < 3; ++i) std::memcpy(coef[i], &q[i], sizeof coef[i]);
  _mm256_zeroupper();
  for (int k = 0; k < 4; ++k) {
    RootList& list = out[k];
    if (((slow >> k) & 1) != 0) {
      list = list_real_roots({coef[0][k], coef[1][k], coef[2][k], 0.0, 0.0}, t0, t1);
      continue;
    }
    list.n = static_cast<std::size_t>(((one >> k) & 1) + ((two >> k) & 1));
    list.x[0] = first[k];
    list.x[1] = second[k];
  }
}
#endif

}  // namespace

Intervals slab_times(const AxisQuadratic& c, const AxisQuadratic& lo, const AxisQuadratic& hi,
                     double t0, double t1) {
  // Lane 0 the lower bound's difference, lane 1 the upper's.
  using O = NarrowOps;
  const O::V q[3] = {O::V{c.c0, c.c0} - O::V{lo.c0, hi.c0}, O::V{c.c1, c.c1} - O::V{lo.c1, hi.c1},
                     O::V{c.c2, c.c2} - O::V{lo.c2, hi.c2}};
  const LaneRootsOf<O> r = lane_roots<O>(q, O::splat(t0), O::splat(t1));
  return pieces_inside(c, lo, hi, t0, t1, lane_root_list(r, 0, q, t0, t1),
                       lane_root_list(r, 1, q, t0, t1));
}

void slab_times(const Slab& a, const Slab& b, double t0, double t1, Intervals (&out)[2],
                bool allow_wide) {
#if defined(FRAGSIM_WIDE_LANES)
  if (allow_wide && has_wide_lanes()) {
    RootList roots[4];
    bound_roots_wide(a, b, t0, t1, roots);
    out[0] = pieces_inside(a.c, a.lo, a.hi, t0, t1, roots[0], roots[1]);
    out[1] = pieces_inside(b.c, b.lo, b.hi, t0, t1, roots[2], roots[3]);
    return;
  }
#else
  (void)allow_wide;
#endif
  out[0] = slab_times(a.c, a.lo, a.hi, t0, t1);
  out[1] = slab_times(b.c, b.lo, b.hi, t0, t1);
}

}  // namespace fragsim
