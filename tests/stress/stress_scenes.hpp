#pragma once
// The stress suite's scenes: fixed corner cases and seeded random scenes that
// span the extremes of docs/method.md section 7. Every case is a plain Scene, so a failure is
// reproduced from the printed INI alone (`fragsim compare --scene case.ini`).

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

#include "sim/scene.hpp"

namespace fragsim::stress {

// How much work a case may do. The suite's run time is set by two budgets of fragment-steps per
// scene (one fragment advanced one step = 1); a case with many fragments gets few steps.
struct Budget {
  double scale = 1.0;                      // FRAGSIM_STRESS_SCALE, or the sanitizer default
  long fragment_steps = 200'000;           // fragment collisions off (each fragment its own island)
  long collision_fragment_steps = 40'000;  // fragment collisions on (QuickStep, SAP pairs)
  int max_steps = 300;                     // "a few hundred"
  int min_steps = 2;

  // The steps a scene of `fragments` fragments gets.
  int steps_for(int fragments, bool collisions) const;
};

// The budget for this process: FRAGSIM_STRESS_SCALE (a number > 0) if set, else 1, or 0.25 in a
// build with AddressSanitizer (__SANITIZE_ADDRESS__), where the instrumented strategies and
// metrics run several times slower.
Budget budget_from_environment();

struct StressCase {
  std::string id;           // "corner/<name>" or "random/<seed>"
  std::uint64_t seed = 0;   // generator seed of a random case (also its simulation.seed)
  std::string description;  // the extremes it combines, one line
  Scene scene;
};

// gtest prints a case by its id and description.
inline void PrintTo(const StressCase& c, std::ostream* out) {
  *out << c.id << ": " << c.description;
}

// How the camera moves during a case.
enum class CameraMotion {
  kStill,      // one waypoint
  kMaxSpeed,   // a straight line at camera.speed_mps = camera.max_speed_mps
  kReversing,  // waypoints alternating between two points speed * dt apart: it turns every step
  kPlayer,     // camera.mode = player at V_c = speed (instant turns and a change of mind every
               // step in the corner cases; drawn bounds in the random ones)
  kTrack,      // camera.mode = track: a seeded random walk at up to V_c = speed, turning as it
               // goes, written as a camera track file (track_dir()) and read back
};

// Where random track cases write their camera track files (FRAGSIM_STRESS_DIR if set, else the
// system's temporary folder). A file's name and content are fixed by the case's seed, so two
// processes writing the same case write the same bytes.
std::string track_dir();

// Where the object (and so the blast) is, relative to the camera's first eye position.
enum class Placement {
  kAhead,   // 1 to 30 m in front
  kAtEye,   // centred on the eye: fragments spawn in and around the camera body
  kBehind,  // 0.3 to 5 m behind the eye
  kAtLens,  // 0.05 m in front of the eye
};

// The hand-made extremes, each named for what it combines.
std::vector<StressCase> corner_cases(const Budget& budget);

// One seeded random scene; the same seed gives the same scene on every platform (fragsim's
// Random, not std::uniform_real_distribution).
StressCase random_case(std::uint64_t seed, const Budget& budget);

// Not in the matrix: a blast of splits^3 fragments aimed at a still camera (40 m/s, zero gravity,
// dt 0.1 s, exact solver), so that hundreds of fragments hit the `wall` strategy's box in the
// same step. Measured on 2 cores: 138 fragments on the wall in one step 0.19 s, 341 (splits 14)
// 3.6 s, 615 (splits 18) 32 s: the exact solver is cubic in an island and the kinematic wall
// joins every fragment touching it into one island.
StressCase wall_island_case(int splits);

// The whole matrix: the corner cases, then random_case(1 .. random_count).
std::vector<StressCase> all_cases(const Budget& budget, int random_count);

}  // namespace fragsim::stress
