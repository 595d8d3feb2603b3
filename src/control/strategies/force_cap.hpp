#pragma once
// Every force-applying strategy goes through this acceleration cap, so no imposed acceleration
// exceeds a_max and no non-finite force ever reaches the physics.

#include <Eigen/Core>
#include <cmath>

#include "control/geometry/vec3_sums.hpp"
#include "control/strategies/strategy.hpp"

namespace fragsim {

// Adds `force_N` on `fragment` to `out`, scaled down to mass_kg * a_max_mps2 if above; counts the
// fragment in out.activity.capped. A non-finite force (a singular spot that escaped its guard) is
// dropped and counted in out.activity.guarded.
inline void apply_capped(StepOutput& out, int fragment, const Eigen::Vector3d& force_N,
                         double mass_kg, double a_max_mps2) {
  if (!force_N.allFinite()) {
    ++out.activity.guarded;
    return;
  }
  const double limit_N = mass_kg * a_max_mps2;
  double norm_N = norm3(force_N);
  // The squares overflow above about 1e154 N and vanish below about 1e-154 N, so there the norm is
  // taken with scaling. Elsewhere it is the plain norm, whose bits the pinned results rely on.
  if (!std::isfinite(norm_N) || norm_N < 1e-150) norm_N = force_N.stableNorm();
  if (norm_N == 0.0) return;
  // A force built as exactly m a_max (deflect-all) must not count as capped through rounding.
  if (norm_N > limit_N * (1.0 + 1e-12)) {
    out.activity.capped.push_back(fragment);
    if (limit_N <= 0.0) return;
    out.forces.push_back({fragment, force_N * (limit_N / norm_N)});
    return;
  }
  out.forces.push_back({fragment, force_N});
}

}  // namespace fragsim
