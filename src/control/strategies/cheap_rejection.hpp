#pragma once
// The cheap rejection's conservative tests settle, before any root solve, that a fragment's
// ballistic path cannot meet a region, namely the camera's reachable ball (`edge`, docs/method.md
// section 3; ball_clearance.hpp), a box (box_clearance.hpp), and edge-min's protected and grown
// boxes in one pass (`edge-min`, section 4; two_box_clearance.hpp). They only ever answer
// "certainly clear"; anything in doubt goes on to the exact solve, so the strategies' results do
// not change. Each keeps a margin far beyond the root solver's rounding (first_root.hpp judges
// "touching" within ~1e-15 of the terms' size), so a path these call clear, the exact solve finds
// clear.
//
// Each test comes twice, for one path, and batched with the same answers, as passes over many paths
// two (or four) at a time without a branch on the data inside a pass, so the processor overlaps
// paths instead of waiting on each one's latency chain.
//
// Here is what their implementations share, a few lane helpers and the box test in lanes, which
// both the box test and the two-box test run. Only ball_clearance.cpp, box_clearance.cpp and
// two_box_clearance.cpp include it, as it brings lane_ops.hpp, whose includers keep -Wpsabi off.

#include <Eigen/Core>
#include <cmath>

#include "control/strategies/lane_ops.hpp"
#include "control/strategies/lanes.hpp"

namespace fragsim::rejection {

using lanes::Lanes;
using lanes::Mask;

[[gnu::always_inline]] inline Lanes l1(const Lanes (&x)[3]) {
  return lanes::abs(x[0]) + lanes::abs(x[1]) + lanes::abs(x[2]);
}

// In lanes of either width (Lanes, and the four-lane rejection's).
template <class V>
[[gnu::always_inline]] inline V dot(const V (&x)[3], const V (&y)[3]) {
  return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
}

inline void broadcast3(const Eigen::Vector3d& x, Lanes (&out)[3]) {
  for (int i = 0; i < 3; ++i) out[i] = lanes::broadcast(x[i]);
}

// ---- The box test -------------------------------------------------------------------------------

// edge-min's two-box rejection runs the box test over every fragment, so it comes in two widths,
// two lanes and (with AVX2) four, as the same templates over lane_ops.hpp's NarrowOps and WideOps,
// so with the same answers, bit for bit, whatever the width.

// The margin, relative to the path's extent and the box's size. The exact solves find the times a
// coordinate meets a face to within ~1e-15 of those sizes (in the coordinate), and 1e-6 is a
// billion times that, micrometres on a scene's metres.
constexpr double kBoxMargin = 1e-6;

// The acceleration (halved) shared by the paths of a box test, with the reciprocals its vertex
// times and roots need, for a multiplication instead of a division per path. The times come out
// within an ulp or two of the quotients, far inside the margin. In lanes of either width.
template <class O>
struct BoxAccelOf {
  using V = typename O::V;
  V a[3];
  // -1 / (2 a), or 0 where a = 0 (no vertex), is the vertex's time per unit of velocity. The sign
  // is here since c1 (-1 / (2 a)) is -c1 / (2 a) exactly, and a NaN's sign is never seen.
  V minus_inv_2a[3];
  V inv_a_z;       // 1 / a_z, or 0
  bool curved[3];  // a != 0
  V reach_m;       // |a|_1 t_end^2 + |lo|_1 + |hi|_1, the part of the margin's scale all share
};
using BoxAccel = BoxAccelOf<NarrowOps>;
inline BoxAccel box_accel(const Eigen::Vector3d& a_mps2, const Eigen::Vector3d& lo_m,
                          const Eigen::Vector3d& hi_m, double t_end_s) {
  BoxAccel acc;
  double inv_2a[3];
  for (int i = 0; i < 3; ++i) {
    acc.a[i] = lanes::broadcast(a_mps2[i]);
    acc.curved[i] = a_mps2[i] != 0.0;
    inv_2a[i] = acc.curved[i] ? 1.0 / (2.0 * a_mps2[i]) : 0.0;
    acc.minus_inv_2a[i] = lanes::broadcast(-inv_2a[i]);
  }
  acc.inv_a_z = lanes::broadcast(inv_2a[2]) + lanes::broadcast(inv_2a[2]);
  acc.reach_m = lanes::broadcast(a_mps2.lpNorm<1>() * t_end_s * t_end_s + lo_m.lpNorm<1>() +
                                 hi_m.lpNorm<1>());
  return acc;
}

template <class O>
[[gnu::always_inline]] inline typename O::V l1_of(const typename O::V (&x)[3]) {
  return O::abs(x[0]) + O::abs(x[1]) + O::abs(x[2]);
}

template <class V>
[[gnu::always_inline]] inline V at(V c0, V c1, V c2, V t) {
  return c0 + t * (c1 + t * c2);
}

// Whether c0 + c1 t + c2 t^2 stays outside [lo, hi] over [t0, t1], i.e. its range there (the ends,
// and the vertex where it lies inside) misses the slab. `curved` says c2 != 0 (the same for all
// paths, as the acceleration's component), minus_inv_2c2 is -1 / (2 c2). kFromStart means t0 = 0,
// where the value is c0 itself when c1 and c2 are finite (c0 + 0 (c1 + 0 c2) differs from it at
// most in a zero's sign, which the comparisons below do not see), and is only for a caller whose
// answer is void where they are not.
template <class O, bool kFromStart = false, class V = typename O::V>
[[gnu::always_inline]] inline typename O::M misses(V c0, V c1, V c2, V minus_inv_2c2, bool curved,
                                                   V t0, V t1, V lo, V hi) {
  const V f0 = kFromStart ? c0 : at(c0, c1, c2, t0);
  const V f1 = at(c0, c1, c2, t1);
  V low = O::min(f0, f1);
  V high = O::max(f0, f1);
  if (curved) {
    const V ts = c1 * minus_inv_2c2;
    const typename O::M vertex_inside = O::gt(ts, t0) & O::lt(ts, t1);
    const V fv = O::select(vertex_inside, at(c0, c1, c2, ts), f0);
    low = O::min(low, fv);
    high = O::max(high, fv);
  }
  return O::lt(high, lo) | O::gt(low, hi);
}

// Widens [first, last] to hold t where `ok` and 0 <= t <= t_end.
template <class O, class V = typename O::V>
[[gnu::always_inline]] inline void include(typename O::M ok, V t, V t_end, V& first, V& last) {
  const typename O::M in = ok & O::ge(t, V{}) & O::le(t, t_end);
  first = O::select(in, O::min(first, t), first);
  last = O::select(in, O::max(last, t), last);
}

// The box grown by `grow` and kept `tol` away, lo - grow - tol <= x(t) <= hi + grow + tol. Not
// usable (never clear) when the margin or the interval is not a finite, non-negative number.
template <class O>
struct GrownBox {
  typename O::V lo[3];
  typename O::V hi[3];
  typename O::M usable;
};
template <class O, class V = typename O::V>
[[gnu::always_inline]] inline GrownBox<O> grow_box(const V (&d)[3], const V (&v)[3],
                                                   const V (&lo_m)[3], const V (&hi_m)[3], V grow,
                                                   V t_end, V reach_m) {
  // The scale bounds every coordinate's reach and the grown box's faces (|lo - grow| <= |lo| +
  // grow).
  const V scale = l1_of<O>(d) + l1_of<O>(v) * t_end + reach_m + 6.0 * O::abs(grow);
  const V tol = kBoxMargin * scale;
  GrownBox<O> box;
  for (int i = 0; i < 3; ++i) {
    box.lo[i] = lo_m[i] - grow - tol;
    box.hi[i] = hi_m[i] + grow + tol;
  }
  const V zero{};
  box.usable = O::eq(tol - tol, zero) & O::ge(t_end, zero);
  return box;
}

// The first stage, whether some coordinate stays outside its slab over the whole interval. Void
// where the box is not usable, as its scale then holds a non-finite d, v or a (the reach), so where
// it is usable all three are finite, as misses<O, true> asks.
template <class O, class V = typename O::V>
[[gnu::always_inline]] inline typename O::M box_ranges_miss(const V (&d)[3], const V (&v)[3],
                                                            const BoxAccelOf<O>& acc,
                                                            const GrownBox<O>& box, V t_end) {
  const V zero{};
  typename O::M miss = misses<O, true>(d[0], v[0], acc.a[0], acc.minus_inv_2a[0], acc.curved[0],
                                       zero, t_end, box.lo[0], box.hi[0]);
  for (int i = 1; i < 3; ++i) {
    miss = miss | misses<O, true>(d[i], v[i], acc.a[i], acc.minus_inv_2a[i], acc.curved[i], zero,
                                  t_end, box.lo[i], box.hi[i]);
  }
  return miss;
}

// The second stage, whether x or y stays outside its slab over the times z is inside its own. Those
// times lie between the first and the last of: the ends of [0, t_end] where z is inside, and the
// times z crosses a face (stable quadratic roots).
template <class O, class V = typename O::V>
[[gnu::always_inline]] inline typename O::M box_window_miss(const V (&d)[3], const V (&v)[3],
                                                            const BoxAccelOf<O>& acc,
                                                            const GrownBox<O>& box, V t_end) {
  const V zero{};
  V first = O::splat(INFINITY);
  V last = O::splat(-INFINITY);
  for (const V t : {zero, t_end}) {
    const V z = at(d[2], v[2], acc.a[2], t);
    include<O>(O::ge(z, box.lo[2]) & O::le(z, box.hi[2]), t, t_end, first, last);
  }
  const V a = acc.a[2];
  const V b = v[2];
  for (const V face : {box.lo[2], box.hi[2]}) {
    const V c = d[2] - face;
    if (!acc.curved[2]) {
      include<O>(O::ne(b, zero), -c / b, t_end, first, last);
      continue;
    }
    const V disc = b * b - 4.0 * a * c;
    const V q = -0.5 * (b + O::copysign(O::sqrt(disc), b));
    include<O>(O::ge(disc, zero), q * acc.inv_a_z, t_end, first, last);
    include<O>(O::ge(disc, zero) & O::ne(q, zero), c / q, t_end, first, last);
  }
  const typename O::M window = O::le(first, last);
  // x and y over that window, widened anyway for its roots' rounding and multiplied reciprocal.
  const V widen = kBoxMargin * t_end;
  const V w0 = O::max(first - widen, zero);
  const V w1 = O::min(last + widen, t_end);
  typename O::M miss = O::none_of(window);
  for (int i = 0; i < 2; ++i) {
    miss = miss | (window & misses<O>(d[i], v[i], acc.a[i], acc.minus_inv_2a[i], acc.curved[i], w0,
                                      w1, box.lo[i], box.hi[i]));
  }
  return miss;
}

// Both stages, the box test for a lane's worth of paths at once, each over its own [0, t_end];
// reach_m is |a|_1 t_end^2 + |lo|_1 + |hi|_1 (BoxAccel::reach_m when all share one interval). Lanes
// in `settled` (a bit each) are answered too but ignored, so the window's roots come only where the
// ranges left a path in doubt that matters, the same answers, cheaper.
template <class O, class V = typename O::V>
[[gnu::always_inline]] inline typename O::M box_clear(const V (&d)[3], const V (&v)[3],
                                                      const BoxAccelOf<O>& acc, const V (&lo_m)[3],
                                                      const V (&hi_m)[3], V grow, V t_end,
                                                      V reach_m, int settled) {
  const GrownBox<O> box = grow_box<O>(d, v, lo_m, hi_m, grow, t_end, reach_m);
  const typename O::M by_ranges = box.usable & box_ranges_miss<O>(d, v, acc, box, t_end);
  if ((O::bits(by_ranges) | settled) == (1 << O::kWidth) - 1) return by_ranges;
  return by_ranges | (box.usable & box_window_miss<O>(d, v, acc, box, t_end));
}
[[gnu::always_inline]] inline Mask box_clear(const Lanes (&d)[3], const Lanes (&v)[3],
                                             const BoxAccel& acc, const Lanes (&lo_m)[3],
                                             const Lanes (&hi_m)[3], Lanes grow, Lanes t_end) {
  return box_clear<NarrowOps>(d, v, acc, lo_m, hi_m, grow, t_end, acc.reach_m, 0);
}

}  // namespace fragsim::rejection
