#pragma once
// The sums over a 3-vector's components (dot product, squared norm, norm) in one fixed order,
// (x + y) + z, instead of Eigen's dot(), squaredNorm() and norm(). Eigen associates such a sum as
// the build's vector width allows, as (x + y) + z with two doubles a register (SSE2, NEON), but
// x + (y + z) with none (WebAssembly without SIMD) or four (AVX), and the last bit of a force then
// depends on how the library was compiled. Spelled out, every build computes the bits the x86-64
// build computes, which the tool's pinned results and the replays of its dumps rely on.

#include <Eigen/Core>
#include <cmath>

namespace fragsim {

inline double dot3(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return (a.x() * b.x() + a.y() * b.y()) + a.z() * b.z();
}

inline double squared_norm3(const Eigen::Vector3d& a) {
  return dot3(a, a);
}

inline double norm3(const Eigen::Vector3d& a) {
  return std::sqrt(squared_norm3(a));
}

}  // namespace fragsim
