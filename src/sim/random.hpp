#pragma once
// A seeded random source whose numbers are the same on every platform and standard library
// (std::uniform_real_distribution is not specified bit for bit).

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

}  // namespace fragsim
