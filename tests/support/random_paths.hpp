#pragma once
// Paths for the cheap rejection's tests (tests/strategies/*_clearance_test.cpp): random
// directions, random paths near a box that graze its faces, and the exact answer whether a path
// enters a box, which whatever the rejection calls clear must agree with.

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "control/geometry/first_root.hpp"
#include "control/geometry/parabola.hpp"

namespace fragsim::test {

inline Eigen::Vector3d random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  return Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
}

// Every time in [0, t_end] where lo <= x(t) <= hi holds for all three coordinates, found from
// the roots of each coordinate against each face (between consecutive break times nothing
// changes), checked at the break times (with a tolerance far below the rejection's margin, so a
// touch counts) and between them.
inline bool enters_box(const Parabola& p, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                       double t_end) {
  std::vector<double> times{0.0, t_end};
  for (int i = 0; i < 3; ++i) {
    for (double face : {lo[i], hi[i]}) {
      for (double r : real_roots({p.p0_m[i] - face, p.v0_mps[i], p.half_accel_mps2()[i], 0.0, 0.0},
                                 0.0, t_end)) {
        times.push_back(r);
      }
    }
  }
  std::sort(times.begin(), times.end());
  const double scale = p.p0_m.lpNorm<1>() + p.v0_mps.lpNorm<1>() * t_end +
                       p.half_accel_mps2().lpNorm<1>() * t_end * t_end + lo.lpNorm<1>() +
                       hi.lpNorm<1>();
  const auto inside = [&](double t, double tol) {
    for (int i = 0; i < 3; ++i) {
      const double x = p.p0_m[i] + t * (p.v0_mps[i] + t * p.half_accel_mps2()[i]);
      if (x < lo[i] - tol || x > hi[i] + tol) return false;
    }
    return true;
  };
  for (std::size_t k = 0; k < times.size(); ++k) {
    if (inside(times[k], 1e-12 * scale)) return true;
    if (k + 1 < times.size() && inside(0.5 * (times[k] + times[k + 1]), 0.0)) return true;
  }
  return false;
}

// Random paths near the box: aimed at a random point of the box grown by up to 1 m (so many pass
// close by), possibly grazing a face at a random time within +-1e-13..1e-1 m.
inline Parabola random_box_path(std::mt19937_64& rng, Eigen::Vector3d& lo, Eigen::Vector3d& hi,
                                double& t_end) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto log_uniform = [&](double lo_exp, double hi_exp) {
    return std::pow(10.0, lo_exp + (hi_exp - lo_exp) * u(rng));
  };
  for (int i = 0; i < 3; ++i) {
    lo[i] = -log_uniform(-2, 0);
    hi[i] = log_uniform(-2, 0);
  }
  t_end = log_uniform(-2, 1);
  Eigen::Vector3d g = Eigen::Vector3d::Zero();
  if (u(rng) < 0.7) g = 20.0 * u(rng) * random_unit(rng);
  const double t_hit = t_end * u(rng) * 1.2;
  Eigen::Vector3d target;
  for (int i = 0; i < 3; ++i) target[i] = lo[i] - 1.0 + (hi[i] - lo[i] + 2.0) * u(rng);
  const int face = static_cast<int>(u(rng) * 7.0);  // 6: no face
  const double delta = (u(rng) < 0.5 ? -1.0 : 1.0) * log_uniform(-13, -1);
  if (face < 6) {
    const int axis = face / 2;
    target[axis] = (face % 2 == 0 ? lo[axis] : hi[axis]) + delta;
  }
  const Eigen::Vector3d start = target + log_uniform(-1, 2) * random_unit(rng);
  // x(t_hit) = target; a grazing one has x'(t_hit) = 0 along the face's axis.
  Eigen::Vector3d v = (target - start) / std::max(t_hit, 1e-3) - 0.5 * g * t_hit;
  Parabola p{start, v, 0.5 * g};
  if (face < 6) {
    const int axis = face / 2;
    // Vertex of that coordinate at t_hit, passing through target there.
    p.v0_mps[axis] = -2.0 * p.half_accel_mps2()[axis] * t_hit;
    p.p0_m[axis] = target[axis] - t_hit * (p.v0_mps[axis] + t_hit * p.half_accel_mps2()[axis]);
  }
  return p;
}

}  // namespace fragsim::test
