#pragma once
// When a ballistic path comes down through a level plane (the ground, or the height a look-ahead
// ends at), as the later root of h(t) = c + b t + a t^2, the path's height above the plane, where h
// is falling, if it lies ahead (t > 0). The one formula behind edge's t_G (time_to_horizon, one
// path or two at once) and edge-min's time to the ground.
//
// The roots are the stable ones, q / a and c / q with q = -(b + sign(b) sqrt(b^2 - 4 a c)) / 2, so
// neither subtracts nearly equal numbers. The formula is written once over an operation set
// (ScalarOps below, lanes::LaneOps for two paths at once) as selections, not branches, so every
// width computes the same IEEE operations in the same order, to the same bits.

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "control/geometry/parabola.hpp"

namespace fragsim {

// The operations time_to_plane_s needs, on one double.
struct ScalarOps {
  using V = double;
  using M = bool;
  static V splat(double x) { return x; }
  static M lt(V a, V b) { return a < b; }
  static M gt(V a, V b) { return a > b; }
  static M ge(V a, V b) { return a >= b; }
  static M ne(V a, V b) { return a != b; }
  static M both(M a, M b) { return a && b; }
  static V select(M m, V a, V b) { return m ? a : b; }
  static V sqrt(V x) { return std::sqrt(x); }
  static V copysign(V mag, V sign) { return std::copysign(mag, sign); }
  static V max(V a, V b) { return std::max(a, b); }
};

// The time h(t) = c + b t + a t^2 comes down through 0 for good (the later root, h falling
// there, t > 0), or `none` where it does not. The a = 0 (no gravity along the plane's normal)
// case is the line's root. Never NaN unless `none` is.
template <class Ops>
typename Ops::V time_to_plane_s(double a, typename Ops::V b, typename Ops::V c,
                                typename Ops::V none) {
  using V = typename Ops::V;
  const V zero = Ops::splat(0.0);
  V later;
  if (a != 0.0) {
    const V disc = b * b - 4.0 * a * c;
    const V q = -0.5 * (b + Ops::copysign(Ops::sqrt(disc), b));
    const V r1 = q / a;
    const V r2 = Ops::select(Ops::ne(q, zero), c / q, r1);
    later = Ops::select(Ops::ge(disc, zero), Ops::max(r1, r2), Ops::splat(-1.0));
  } else {
    later = Ops::select(Ops::ne(b, zero), -c / b, Ops::splat(-1.0));
  }
  // Ahead, and coming down there (a NaN root fails both).
  const auto down_ahead = Ops::both(Ops::gt(later, zero), Ops::lt(b + 2.0 * a * later, zero));
  return Ops::select(down_ahead, later, none);
}

// The time one path comes down through the plane, or nothing, from its height above the plane as a
// coordinate's quadratic c0 + c1 t + c2 t^2.
inline std::optional<double> time_to_plane_s(const AxisQuadratic& height_m) {
  constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
  const double t = time_to_plane_s<ScalarOps>(height_m.c2, height_m.c1, height_m.c0, kNone);
  if (std::isnan(t)) return std::nullopt;
  return t;
}

}  // namespace fragsim
