#pragma once
// A seeded random source whose numbers are the same on every platform and standard library
// (std::uniform_real_distribution is not specified bit for bit).

#include <Eigen/Core>
#include <cstdint>
#include <random>

namespace fragsim {

class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}
  // Uniform in [0, 1).
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

 private:
  std::mt19937_64 engine_;
};

// A uniform random point in the unit ball, by rejection (the same sequence everywhere).
inline Eigen::Vector3d random_in_unit_ball(Random& rng) {
  for (;;) {
    Eigen::Vector3d v(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    if (v.squaredNorm() <= 1.0) return v;
  }
}

}  // namespace fragsim
