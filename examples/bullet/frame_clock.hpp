// Rendered frame times of a game whose frame rate wanders between 30 and 144 Hz: the physics sees
// a different split of the frames into fixed substeps every run, and the same split for the same
// seed. Never the wall clock.
#pragma once

#include <cstdint>

#include "seeded_draws.hpp"

class FrameClock {
 public:
  static constexpr double kShortestFrame_s = 1.0 / 144.0;
  static constexpr double kLongestFrame_s = 1.0 / 30.0;

  explicit FrameClock(uint64_t seed) : draws_(seed) {}

  double next_frame_s() { return draws_.uniform(kShortestFrame_s, kLongestFrame_s); }

 private:
  SeededDraws draws_;
};
