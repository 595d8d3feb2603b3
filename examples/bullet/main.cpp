// fragsim_control in a second engine: Bullet's btDiscreteDynamicsWorld, stepped at a fixed 1/120 s
// substep under a frame rate that wanders between 30 and 144 Hz, the controller called from
// Bullet's own pre-tick callback once per substep (see README.md for the lines that matter).
// Twenty seeded blasts at seeded camera moves, each without and with the controller, first with
// fragments colliding with the ground only, then with each other too; the example's own
// near-plane check counts the fragments that met the near rectangle. Exits 0 only when, with
// fragment collisions off and on, most runs without the controller are hit and no run with it is.
#include <LinearMath/btScalar.h>
#include <fragsim/control.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <utility>
#include <vector>

#include "blast_run.hpp"
#include "near_plane_check.hpp"

namespace {

constexpr int kRuns = 20;

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const size_t mid = values.size() / 2;
  return values.size() % 2 ? values[mid] : 0.5 * (values[mid - 1] + values[mid]);
}

struct Tally {
  int runs_hit_unprotected = 0;  // runs with at least one hit, without the controller
  int runs_hit_protected = 0;    // ... with it
  int hits_unprotected = 0, hits_protected = 0;
  double last_hit_s = 0;  // the latest first hit of any run, either way
  bool failed = false;    // a run that could not go through (a refused call, a dropped substep)
  uint32_t warnings = 0;
  std::vector<double> controller_ns, bullet_ns, ratio;  // per fragment per (sub)step
};

// Runs every seed without and with the controller; prints one line per seed.
Tally run_all(bool fragment_collisions) {
  std::printf("\nfragment collisions %s\n", fragment_collisions ? "ON" : "OFF");
  std::printf("seed  camera    frames  substeps  hits none  hits edge-min  pushed  capped\n");
  Tally tally;
  for (int seed = 1; seed <= kRuns; ++seed) {
    RunSettings settings;
    settings.seed = static_cast<uint64_t>(seed);
    settings.move = static_cast<CameraMove>(seed % 4);
    settings.fragment_collisions = fragment_collisions;
    settings.protect = false;
    const RunResult none = run_blast(settings);
    settings.protect = true;
    const RunResult edge_min = run_blast(settings);
    for (const RunResult* r : {&none, &edge_min}) {
      if (!r->error.empty()) {
        std::fprintf(stderr, "bullet_world: seed %d: %s\n", seed, r->error.c_str());
        tally.failed = true;
      }
    }
    std::printf("%4d  %-8s  %6d  %8d  %9d  %13d  %6d  %6lld\n", seed,
                camera_move_name(settings.move), edge_min.frames, edge_min.substeps,
                none.hit_fragments, edge_min.hit_fragments, edge_min.pushed_fragments,
                static_cast<long long>(edge_min.capped));
    tally.runs_hit_unprotected += none.hit_fragments > 0;
    tally.runs_hit_protected += edge_min.hit_fragments > 0;
    tally.hits_unprotected += none.hit_fragments;
    tally.hits_protected += edge_min.hit_fragments;
    tally.last_hit_s = std::max({tally.last_hit_s, none.last_hit_s, edge_min.last_hit_s});
    tally.warnings |= edge_min.warnings;
    const double fragment_substeps = static_cast<double>(edge_min.fragments) * edge_min.substeps;
    tally.controller_ns.push_back(1e9 * edge_min.controller_s / fragment_substeps);
    tally.bullet_ns.push_back(1e9 * edge_min.bullet_s / fragment_substeps);
    tally.ratio.push_back(edge_min.controller_s / edge_min.bullet_s);
  }
  std::printf(
      "runs with a hit: none %d of %d (%d fragments), edge-min %d of %d (%d fragments); "
      "latest hit at %.3f s of %.2f\n",
      tally.runs_hit_unprotected, kRuns, tally.hits_unprotected, tally.runs_hit_protected, kRuns,
      tally.hits_protected, tally.last_hit_s, kDuration_s);
  return tally;
}

// Wall-clock figures: they vary from run to run, unlike every count above.
void print_cost(const char* label, const Tally& t) {
  std::printf(
      "cost, collisions %s (medians over %d runs): controller %.1f ns/fragment/step, "
      "Bullet's stepSimulation %.1f ns/fragment/substep, ratio %.3f\n",
      label, kRuns, median(t.controller_ns), median(t.bullet_ns), median(t.ratio));
}

}  // namespace

int main() {
  if (!near_plane_check_agrees_with_known_cases()) {
    std::fprintf(stderr, "bullet_world: the near-plane check got a hand-worked case wrong\n");
    return 1;
  }
  std::printf(
      "Bullet %d (btScalar of %zu bytes), %.2f s at a 1/%.0f s substep, frames of "
      "1/144 to 1/30 s, %d seeds\n",
      btGetVersion(), sizeof(btScalar), kDuration_s, 1 / kSubstep_s, kRuns);
  const Tally off = run_all(false);
  const Tally on = run_all(true);
  std::printf("\n");
  print_cost("off", off);
  print_cost("on", on);

  bool ok = !off.failed && !on.failed;
  // Fragment collisions bend paths the controller predicts as parabolas, re-solved every
  // substep; on Bullet 3.24 these runs are as clean as the ones without, so they are held to the
  // same two rules.
  for (const auto& [label, t] : {std::pair{"off", &off}, std::pair{"on", &on}}) {
    // The scene must threaten the camera honestly, or a clean protected run proves nothing.
    if (2 * t->runs_hit_unprotected <= kRuns) {
      std::fprintf(stderr,
                   "bullet_world: collisions %s: only %d of %d runs without the "
                   "controller were hit\n",
                   label, t->runs_hit_unprotected, kRuns);
      ok = false;
    }
    if (t->runs_hit_protected != 0) {
      std::fprintf(stderr,
                   "bullet_world: collisions %s: edge-min let %d fragments through in %d "
                   "runs\n",
                   label, t->hits_protected, t->runs_hit_protected);
      ok = false;
    }
  }
  // The camera paths keep their declared bounds, the units are the library's and every fragment
  // has a mass: a warning of these kinds (over speed, a field of view in radians, a skipped or an
  // unprotected fragment) is a bug of this example. FRAGSIM_WARNING_BELOW_GROUND is not: Bullet
  // lets a falling box sink into the ground plane for a substep or two, its centre a few
  // centimetres below it, before the contact pushes it out.
  constexpr unsigned kExampleBugs = FRAGSIM_WARNING_CAMERA_OVER_SPEED |
                                    FRAGSIM_WARNING_FOVY_IN_RADIANS | FRAGSIM_WARNING_SKIPPED |
                                    FRAGSIM_WARNING_UNPROTECTED;
  if (((off.warnings | on.warnings) & kExampleBugs) != 0) {
    std::fprintf(stderr, "bullet_world: the controller warned (bits %u)\n",
                 (off.warnings | on.warnings) & kExampleBugs);
    ok = false;
  }
  std::printf("%s\n", ok ? "bullet_world: ok" : "bullet_world: FAILED");
  return ok ? 0 : 1;
}
