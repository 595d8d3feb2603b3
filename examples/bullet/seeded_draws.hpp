// Every random number of the example, from a seed: the same seed draws the same scene, camera and
// frame times with any standard library.
#pragma once

#include <cstdint>
#include <random>

class SeededDraws {
 public:
  explicit SeededDraws(uint64_t seed) : engine_(seed) {}

  // Uniform in [lo, hi). std::uniform_real_distribution is not used: its algorithm is the
  // standard library's choice, so another library could draw other numbers from the same seed.
  double uniform(double lo, double hi) {
    const double unit = static_cast<double>(engine_() >> 11) * 0x1.0p-53;  // [0, 1), 53 bits
    return lo + unit * (hi - lo);
  }

  // A seed for another stream (the frame times), so adding a draw to one stream leaves the other.
  uint64_t next_seed() { return engine_(); }

 private:
  std::mt19937_64 engine_;  // its output sequence is fixed by the standard
};
