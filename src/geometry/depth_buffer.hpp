#pragma once
// What moving the near plane costs. A perspective depth buffer spends its precision near the
// eye, so pulling the near plane in coarsens every depth behind it (thesis fig. 2.6). Shared by
// `near-plane`, which trades it, and the metrics, which report it.

#include <cmath>

namespace fragsim {

// The smallest depth difference a depth buffer of `bits` resolves at distance z_m with the near
// plane at near_m: z^2 / (n 2^b).
inline double depth_step_m(double z_m, double near_m, int bits) {
  return z_m * z_m / (near_m * std::ldexp(1.0, bits));
}

}  // namespace fragsim
