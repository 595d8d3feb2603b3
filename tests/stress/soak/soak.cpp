// fragsim_soak: the stress generator's random scenes (stress_scenes.hpp) by the thousand, every
// strategy on each, for scripts/soak.sh. Per scene it checks what the stress suite checks
// (stress_test.cpp): no non-finite state, force or summary number, no ODE message, no force over
// its cap, no fragment above its energy budget. A crash ends the process: scripts/soak.sh reads
// the last "begin" line to name the seed.
//
// Usage: fragsim_soak FIRST_SEED COUNT
// FRAGSIM_STRESS_SCALE scales each scene's fragment-steps as in the stress suite. Prints one line
// per scene and, at the end, the counts the soak is judged by. Exit 1 on any failed check.

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "experiments/evaluation.hpp"
#include "sim/scene_file.hpp"
#include "sim/scene_strategies.hpp"
#include "sim/world.hpp"
#include "stress/health_observer.hpp"
#include "stress/stress_scenes.hpp"

namespace {

using namespace fragsim;
using namespace fragsim::stress;

// Every floating-point number of a run summary.
std::vector<double> summary_numbers(const RunSummary& s) {
  return {s.dt_s,
          s.deviation.mean_m,
          s.deviation.max_m,
          s.deviation.deviated_share,
          s.occlusion.mean,
          s.occlusion.max,
          s.occlusion.central_mean,
          s.occlusion.central_max,
          s.occlusion.single_fragment_max,
          s.activity.impulse_Ns,
          s.activity.max_accel_mps2,
          s.activity.min_near_m,
          s.activity.depth_step_m,
          s.cost.physics_ms_median,
          s.cost.physics_ms_p95,
          s.cost.strategy_ms_median,
          s.cost.strategy_ms_p95,
          s.cost.wall_s};
}

const char* mode_name(const Scene& s) {
  switch (s.camera.mode) {
    case CameraMode::kPath:
      return "path";
    case CameraMode::kTrack:
      return "track";
    case CameraMode::kPlayer:
      return "player";
  }
  return "?";
}

struct Totals {
  long scenes = 0, runs = 0, failed_scenes = 0;
  long nonfinite = 0, ode_messages = 0, exact_retries = 0, over_cap = 0, energy = 0, unexpected = 0;
  long above_1000 = 0, at_largest = 0, voronoi = 0, gravity_off = 0, collisions = 0;
  long dt_min = 0, dt_max = 0, caps_zero = 0, caps_huge = 0, fast_blast = 0, fast_camera = 0;
  std::map<std::string, long> modes;
  int largest = 0;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: fragsim_soak FIRST_SEED COUNT\n");
    return 2;
  }
  const unsigned long long first = std::strtoull(argv[1], nullptr, 10);
  const long count = std::strtol(argv[2], nullptr, 10);
  if (first < 1 || count < 1) {
    std::fprintf(stderr, "fragsim_soak: FIRST_SEED and COUNT must be >= 1\n");
    return 2;
  }
  const Budget budget = budget_from_environment();
  const std::vector<std::string> strategies = strategy_names();
  Totals t;
  for (long i = 0; i < count; ++i) {
    const std::uint64_t seed = first + static_cast<std::uint64_t>(i);
    std::printf("begin %llu\n", static_cast<unsigned long long>(seed));
    std::fflush(stdout);
    const StressCase c = random_case(seed, budget);
    const Scene& sc = c.scene;
    HealthObserver health;
    const long retries_before = World::exact_step_retries();
    const std::vector<Evaluation> runs = compare(sc, strategies, true, &health);
    t.exact_retries += World::exact_step_retries() - retries_before;
    long bad = 0;
    std::string why;
    auto fail = [&](const std::string& what, long n) {
      if (n == 0) return;
      bad += n;
      if (why.size() < 200) why += " " + what + "=" + std::to_string(n);
    };
    std::map<std::string, const RunHealth*> by_name;
    for (const RunHealth& h : health.runs()) by_name[h.strategy] = &h;
    for (std::size_t r = 0; r < runs.size(); ++r) {
      const RunSummary& s = runs[r].summary;
      if (!by_name.count(s.strategy)) {
        fail(s.strategy + ":unobserved", 1);
        continue;
      }
      const RunHealth& h = *by_name[s.strategy];
      long nonfinite_numbers = 0;
      for (double v : summary_numbers(s)) nonfinite_numbers += std::isfinite(v) ? 0 : 1;
      const long nonfinite = s.health.nonfinite_fragments + h.nonfinite_states +
                             h.nonfinite_forces + h.nonfinite_near + nonfinite_numbers;
      fail(s.strategy + ":nonfinite", nonfinite);
      fail(s.strategy + ":ode", s.health.ode_messages);
      fail(s.strategy + ":over_cap", h.forces_over_cap);
      fail(s.strategy + ":energy", h.energy_violations);
      fail(s.strategy + ":unexpected_force", h.unexpected_forces);
      t.nonfinite += nonfinite;
      t.ode_messages += s.health.ode_messages;
      t.over_cap += h.forces_over_cap;
      t.energy += h.energy_violations;
      t.unexpected += h.unexpected_forces;
      ++t.runs;
    }
    if (runs.size() != strategies.size() || health.runs().size() != strategies.size()) {
      fail("missing_runs", 1);
    }
    const int fragments = sc.fragment_count();
    ++t.scenes;
    t.failed_scenes += bad > 0 ? 1 : 0;
    t.above_1000 += fragments > 1000 ? 1 : 0;
    t.at_largest += fragments >= 27 * 27 * 27 ? 1 : 0;
    t.largest = std::max(t.largest, fragments);
    t.voronoi += sc.object.pattern == DebrisPattern::kVoronoi ? 1 : 0;
    t.gravity_off += sc.sim.gravity_mps2.norm() == 0.0 ? 1 : 0;
    t.collisions += sc.sim.fragment_collisions ? 1 : 0;
    t.dt_min += sc.sim.dt_s <= 1e-3 ? 1 : 0;
    t.dt_max += sc.sim.dt_s >= 0.1 ? 1 : 0;
    t.caps_zero +=
        sc.strategies.edge.a_max_mps2 == 0.0 || sc.strategies.edge_min.a_max_mps2 == 0.0 ? 1 : 0;
    t.caps_huge +=
        sc.strategies.edge.a_max_mps2 >= 1e6 || sc.strategies.edge_min.a_max_mps2 >= 1e6 ? 1 : 0;
    t.fast_blast += sc.explosion.speed_mps >= 200.0 ? 1 : 0;
    t.fast_camera += sc.camera.max_speed_mps >= 100.0 ? 1 : 0;
    ++t.modes[mode_name(sc)];
    std::printf("%s %llu: %d %s, %s camera, %s%s\n", bad ? "FAIL" : "ok",
                static_cast<unsigned long long>(seed), fragments,
                sc.object.pattern == DebrisPattern::kVoronoi ? "cells" : "cubes", mode_name(sc),
                c.description.c_str(), why.c_str());
    if (bad) std::printf("--- scene INI ---\n%s--- end ---\n", scene_to_ini(sc).c_str());
    std::fflush(stdout);
  }
  std::printf(
      "soak: scenes %ld runs %ld failed_scenes %ld nonfinite %ld ode_messages %ld "
      "exact_step_retries %ld over_cap %ld "
      "energy %ld unexpected_forces %ld above_1000 %ld at_largest %ld largest %d voronoi %ld "
      "gravity_off %ld collisions %ld dt_1e-3 %ld dt_0.1 %ld cap_0 %ld cap_1e6 %ld blast_200 %ld "
      "camera_100 %ld",
      t.scenes, t.runs, t.failed_scenes, t.nonfinite, t.ode_messages, t.exact_retries, t.over_cap,
      t.energy, t.unexpected, t.above_1000, t.at_largest, t.largest, t.voronoi, t.gravity_off,
      t.collisions, t.dt_min, t.dt_max, t.caps_zero, t.caps_huge, t.fast_blast, t.fast_camera);
  for (const auto& [mode, n] : t.modes) std::printf(" mode_%s %ld", mode.c_str(), n);
  std::printf("\n");
  return t.failed_scenes > 0 ? 1 : 0;
}
