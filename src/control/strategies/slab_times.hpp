#pragma once
// The times at which one camera-space coordinate of a path, a quadratic in t, lies between two
// bounds that are quadratics in t too (a side of the protected box, or of the grown box, which
// grows with t). edge-min's exact solve intersects about eleven such sets per fragment it solves,
// so this is most of its cost.
//
// The definition sorts the break points t0, t1 and the real roots of c - lo and c - hi in [t0, t1]
// (first_root.hpp's list_real_roots). Each piece between consecutive points is in the set when its
// midpoint is inside, and a path that starts inside has at least {t0}. slab_times computes exactly
// that, bit for bit (tests/strategies/slab_times_test.cpp holds the definition written plainly and
// compares), with the two bounds' roots found together in lanes (two, or four for two slabs at
// once). The quadratics' closed forms, their divisions and square root run once for all;
// list_real_roots itself runs only where a bound needs its rarer branches (a sample that overflows,
// a root the closed form cannot place).

#include "control/geometry/parabola.hpp"
#include "control/strategies/intervals.hpp"

namespace fragsim {

// The times in [t0, t1] where lo(t) <= c(t) <= hi(t).
Intervals slab_times(const AxisQuadratic& c, const AxisQuadratic& lo, const AxisQuadratic& hi,
                     double t0, double t1);

// A fixed slab lo <= c(t) <= hi over [0, horizon] (the constant camera model's box).
inline Intervals slab_times(const AxisQuadratic& c, double lo, double hi, double horizon) {
  return slab_times(c, AxisQuadratic{lo, 0.0, 0.0}, AxisQuadratic{hi, 0.0, 0.0}, 0.0, horizon);
}

// A coordinate and its two bounds.
struct Slab {
  AxisQuadratic c;
  AxisQuadratic lo;
  AxisQuadratic hi;
};

// Two slabs over one interval, out[0] a's times and out[1] b's. The sets are those of one at a
// time, found four lanes at once where the processor has AVX2 (lane_ops.hpp). allow_wide = false
// (for tests) keeps to two lanes even there.
void slab_times(const Slab& a, const Slab& b, double t0, double t1, Intervals (&out)[2],
                bool allow_wide = true);

}  // namespace fragsim
