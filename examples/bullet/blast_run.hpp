// One run: a seeded blast at a seeded camera move in a Bullet world stepped at a fixed substep
// under a varying frame rate, with or without the controller, judged by the near-plane check.
#pragma once

#include <cstdint>
#include <string>

#include "camera_path.hpp"

constexpr double kSubstep_s = 1.0 / 120.0;
// A 1/30 s frame plus the carried remainder (under 1/120 s) needs at most 4; a frame that needed
// more than this would drop time, and the run fails if one does.
constexpr int kMaxSubsteps = 8;
constexpr double kDuration_s = 1.25;

struct RunSettings {
  uint64_t seed = 1;
  CameraMove move = CameraMove::walk_in;
  bool fragment_collisions = false;
  bool protect = false;  // true: edge-min, fragsim's default def; false: no controller
};

struct RunResult {
  std::string error;  // empty when the run went through
  int fragments = 0;
  int frames = 0;
  int substeps = 0;
  int hit_fragments = 0;     // fragments the near-plane check saw meet the near rectangle
  double last_hit_s = 0;     // the end of the substep of the latest first hit (0: none)
  int pushed_fragments = 0;  // fragments that got a nonzero force at least once
  int64_t capped = 0;        // the steps' stats.capped, summed
  uint32_t warnings = 0;     // the steps' stats.warnings, or-ed
  // Wall time (steady clock): inside fragsim_controller_step_arrays, and inside stepSimulation
  // less the example's own tick callbacks (Bullet's own work).
  double controller_s = 0;
  double bullet_s = 0;
};

RunResult run_blast(const RunSettings& settings);
