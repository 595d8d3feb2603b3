// The controller's allocations, counted and made to fail: C++ because only C++ can replace the
// allocation functions (operator new) of a whole program, which is how every allocation the
// library makes is seen here. Built against the library alone, no test framework.
//
// - A steady step (the same ids as the last) allocates nothing, nor does the explosion's step
//   (every id new) after fragsim_controller_reserve; with one camera, and with two set once
//   (two eyes 6.4 cm apart, whose pushes are joined in rounds).
// - For every N, failing the Nth allocation of a step returns FRAGSIM_ERROR_OUT_OF_MEMORY with zero
//   forces and leaves the controller as before the call: the same step retried, and the steps
//   after it, give the forces of a controller that never failed.

#include <fragsim/control.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <vector>

#include "check.h"
#include "replaced_operator_new.hpp"

namespace {

long g_allocations = 0;  // counted while g_counting
bool g_counting = false;
long g_fail_at = 0;  // 0: none; else the allocation (1-based, while counting) that fails

}  // namespace

void* test_allocate(std::size_t n, std::size_t alignment) {
  if (g_counting && ++g_allocations == g_fail_at) throw std::bad_alloc();
  return test_system_block(n, alignment);
}

namespace {

constexpr double kDt = 1.0 / 60.0;
constexpr int kSteps = 10;
constexpr int kFragments = 300;

// A blast 6 m in front of the default camera: fragments thrown every way, some at the lens. At
// step 5 a third of them go (shattered, out of the world) and 40 new ones arrive, so steps 0
// (every id new) and 5 (some new, some gone) re-index, the others are steady.
struct Scenario {
  std::vector<std::vector<fragsim_fragment>> steps;
};

Scenario make_scenario() {
  Scenario s;
  std::vector<fragsim_fragment> now;
  for (int i = 0; i < kFragments; ++i) {
    fragsim_fragment f{};
    const double a = 2.399963 * i;  // the golden angle: directions spread evenly
    const double z = 1.0 - 2.0 * (i + 0.5) / kFragments;
    const double r = std::sqrt(1.0 - z * z);
    f.position_m = {0.0, 0.0, -6.0};
    f.velocity_mps = {6.0 * r * std::cos(a), 6.0 * r * std::sin(a) + 2.0, 6.0 * z + 6.0};
    f.radius_m = 0.04 + 0.0002 * i;
    f.mass_kg = 0.3 + 0.001 * i;
    f.id = 1000 + static_cast<std::uint64_t>(i) * 7;
    now.push_back(f);
  }
  for (int step = 0; step < kSteps; ++step) {
    if (step == 5) {
      std::vector<fragsim_fragment> kept;
      for (std::size_t i = 0; i < now.size(); ++i) {
        if (i % 3 != 1) kept.push_back(now[i]);
      }
      for (int k = 0; k < 40; ++k) {
        fragsim_fragment f = now[static_cast<std::size_t>(k)];
        f.id = 900000 + static_cast<std::uint64_t>(k);
        f.velocity_mps.x = -f.velocity_mps.x;
        kept.push_back(f);
      }
      now = kept;
    }
    s.steps.push_back(now);
    for (fragsim_fragment& f : now) {  // free flight: what the engine would do without forces
      f.velocity_mps.y -= 9.81 * kDt;
      f.position_m.x += f.velocity_mps.x * kDt;
      f.position_m.y += f.velocity_mps.y * kDt;
      f.position_m.z += f.velocity_mps.z * kDt;
    }
  }
  return s;
}

// The cameras of the configuration being checked: 1, walking toward the debris; 2, two eyes
// 6.4 cm apart. Set once on the controller (set_cameras below), their poses per step.
int g_cameras = 1;
fragsim_camera_pose g_poses[2];

void set_cameras(fragsim_controller_id c) {
  const fragsim_camera_def defs[2] = {fragsim_default_camera_def(), fragsim_default_camera_def()};
  if (fragsim_controller_set_cameras(c, defs, g_cameras) != FRAGSIM_OK) std::abort();
}

// One step's call: its input and its fragments.
struct StepCall {
  fragsim_step_input in;
  const fragsim_fragment* fragments;
  int32_t fragment_count;
  fragsim_status run(fragsim_controller_id c, fragsim_vec3* forces) const {
    return fragsim_controller_step(c, &in, fragments, fragment_count, forces, nullptr);
  }
};

StepCall input_at(const Scenario& s, int step) {
  fragsim_step_input in = fragsim_default_step_input();
  in.time_s = step * kDt;
  in.ground_height_m = -1.6;
  for (int j = 0; j < g_cameras; ++j) {
    g_poses[j] = fragsim_default_camera_pose();
    g_poses[j].velocity_mps = {0.0, 0.0, -1.0};
    g_poses[j].eye_m = {0.0, 0.0, -1.0 * step * kDt};
    if (g_cameras == 2) g_poses[j].eye_m.x += j == 0 ? -0.032 : 0.032;
  }
  in.camera_poses = g_poses;
  in.camera_count = g_cameras;
  const std::vector<fragsim_fragment>& f = s.steps[static_cast<std::size_t>(step)];
  return {in, f.data(), static_cast<int32_t>(f.size())};
}

struct Config {
  const char* name;
  fragsim_controller_def def;
};

std::vector<Config> configs() {
  std::vector<Config> c;
  fragsim_controller_def d = fragsim_default_controller_def();
  c.push_back({"edge-min", d});
  d.edge_min.max_solves = 5;
  c.push_back({"edge-min, max_solves 5", d});
  d = fragsim_default_controller_def();
  d.edge_min.camera_model = FRAGSIM_CAMERA_CONSTANT;
  c.push_back({"edge-min, constant camera", d});
  d = fragsim_default_controller_def();
  d.strategy = FRAGSIM_STRATEGY_EDGE;
  c.push_back({"edge", d});
  d.edge.replan = FRAGSIM_EDGE_REPLAN_ALWAYS;
  c.push_back({"edge, replan always", d});
  d = fragsim_default_controller_def();
  d.strategy = FRAGSIM_STRATEGY_DEFLECT_ALL;
  c.push_back({"deflect-all", d});
  return c;
}

using Forces = std::vector<fragsim_vec3>;

fragsim_status step(fragsim_controller_id c, const Scenario& s, int k, Forces& out) {
  const StepCall call = input_at(s, k);
  out.assign(static_cast<std::size_t>(call.fragment_count), fragsim_vec3{7.0, 7.0, 7.0});
  return call.run(c, out.data());
}

bool same(const Forces& a, const Forces& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof a[0]) == 0;
}

bool all_zero(const Forces& f) {
  for (const fragsim_vec3& v : f) {
    if (v.x != 0.0 || v.y != 0.0 || v.z != 0.0) return false;
  }
  return true;
}

// A controller stepped through steps [0, k).
fragsim_controller_id prepared(const Config& cfg, const Scenario& s, int k) {
  fragsim_controller_id c{};
  if (fragsim_controller_create(&cfg.def, &c, nullptr, 0) != FRAGSIM_OK) std::abort();
  set_cameras(c);
  Forces f;
  for (int j = 0; j < k; ++j) {
    if (step(c, s, j, f) != FRAGSIM_OK) std::abort();
  }
  return c;
}

long allocations_of_step(fragsim_controller_id c, const Scenario& s, int k, fragsim_status& st) {
  const StepCall call = input_at(s, k);
  Forces f(static_cast<std::size_t>(call.fragment_count));
  g_allocations = 0;
  g_counting = true;
  st = call.run(c, f.data());
  g_counting = false;
  return g_allocations;
}

void check_config(const Config& cfg, const Scenario& s) {
  // The reference: never failed.
  std::vector<Forces> reference(kSteps);
  {
    const fragsim_controller_id r = prepared(cfg, s, 0);
    for (int k = 0; k < kSteps; ++k)
      CHECK(step(r, s, k, reference[static_cast<std::size_t>(k)]) == FRAGSIM_OK);
    fragsim_controller_destroy(r);
  }
  int pushed = 0;
  for (const Forces& f : reference) pushed += all_zero(f) ? 0 : 1;
  CHECK(pushed > 0);  // the scenario reaches the strategy's forces

  // Steady steps allocate nothing.
  for (int k : {2, 3, 7}) {
    const fragsim_controller_id c = prepared(cfg, s, k);
    fragsim_status st = FRAGSIM_OK;
    const long n = allocations_of_step(c, s, k, st);
    CHECK(st == FRAGSIM_OK);
    if (n != 0) std::fprintf(stderr, "%s: steady step %d: %ld allocations\n", cfg.name, k, n);
    CHECK(n == 0);
    fragsim_controller_destroy(c);
  }

  // Every allocation of a re-indexing step, and of a steady one after a re-index, made to fail.
  long failed_calls = 0;
  for (int k : {0, 1, 5, 6}) {
    const fragsim_controller_id probe = prepared(cfg, s, k);
    fragsim_status st = FRAGSIM_OK;
    const long total = allocations_of_step(probe, s, k, st);
    fragsim_controller_destroy(probe);
    for (long n = 1; n <= total; ++n) {
      const fragsim_controller_id c = prepared(cfg, s, k);
      const StepCall call = input_at(s, k);
      Forces f(static_cast<std::size_t>(call.fragment_count), fragsim_vec3{7.0, 7.0, 7.0});
      g_allocations = 0;
      g_fail_at = n;
      g_counting = true;
      const fragsim_status failed = call.run(c, f.data());
      g_counting = false;
      g_fail_at = 0;
      ++failed_calls;
      CHECK(failed == FRAGSIM_ERROR_OUT_OF_MEMORY);
      CHECK(all_zero(f));
      CHECK(std::strcmp(fragsim_controller_last_error(c), "out of memory") == 0);
      // As before the call: the same step again, and the next two, as if it had never failed.
      for (int j = k; j < k + 3 && j < kSteps; ++j) {
        CHECK(step(c, s, j, f) == FRAGSIM_OK);
        if (!same(f, reference[static_cast<std::size_t>(j)])) {
          std::fprintf(stderr, "%s: allocation %ld of step %d failed: step %d differs\n", cfg.name,
                       n, k, j);
          ++failures;
        }
      }
      fragsim_controller_destroy(c);
    }
  }
  std::printf(
      "%s, %s: %d steps pushed; %ld failed allocations, each left the controller as it was\n",
      cfg.name, g_cameras == 1 ? "one camera" : "two cameras", pushed, failed_calls);

  // After fragsim_controller_reserve the explosion's step (every id new) allocates nothing.
  {
    fragsim_controller_id c{};
    CHECK(fragsim_controller_create(&cfg.def, &c, nullptr, 0) == FRAGSIM_OK);
    set_cameras(c);
    CHECK(fragsim_controller_reserve(c, kFragments) == FRAGSIM_OK);
    fragsim_status st = FRAGSIM_OK;
    const long n = allocations_of_step(c, s, 0, st);
    CHECK(st == FRAGSIM_OK);
    if (n != 0) std::fprintf(stderr, "%s: reserved all-new step: %ld allocations\n", cfg.name, n);
    CHECK(n == 0);
    fragsim_controller_destroy(c);
  }
}

}  // namespace

int main() {
  const Scenario s = make_scenario();
  for (const int cameras : {1, 2}) {
    g_cameras = cameras;
    for (const Config& cfg : configs()) check_config(cfg, s);
  }
  return check_verdict("allocation_test");
}
