// fragsim_controller_def's allocator hook (since 0.6): every allocation of a controller goes
// through it and none through the global operator new, which this program replaces to count (C++
// because only C++ can replace it). Built against the library alone, no test framework.
//
// - One of alloc_fn and free_fn without the other is refused, naming the NULL one.
// - With the hook: create, reserve, steps (re-indexing, steady, the occlusion bound's), reset and
//   destroy call operator new zero times, and every block the hook gave is given back with the
//   size and alignment it was asked for. The one exception, stated in control.h, is process-wide
//   and done once: the first create builds the parameters' rule tables and the id slots' first
//   chunk through operator new; a hookless controller made first takes it here.
// - After create, reserve and one step, a steady step calls neither the hook nor operator new.
// - A hook that fails its Nth call, for every N a step makes, gives FRAGSIM_ERROR_OUT_OF_MEMORY,
//   zero forces and a controller as before the call: the retry and the steps after it give the
//   forces of a controller that never failed. Likewise a create that fails leaks nothing.

#include <fragsim/control.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <new>
#include <vector>

#include "check.h"
#include "replaced_operator_new.hpp"

namespace {

long g_global_news = 0;  // operator new calls while g_watch
bool g_watch = false;

}  // namespace

void* test_allocate(std::size_t n, std::size_t align) {
  if (g_watch) ++g_global_news;
  return test_system_block(n, align);
}

namespace {

// The game's allocator: malloc with a header before each block that records the size and
// alignment asked, checked when the block comes back. Counts its calls and the blocks out, and
// fails its fail_at-th call (0: never).
struct Hook {
  long allocs = 0;
  long frees = 0;
  long live = 0;
  long fail_at = 0;
  long bad_frees = 0;  // a block given back with another size or alignment than asked
};

constexpr std::size_t kHeader = 64;  // keeps any alignment up to 64

void* hook_alloc(size_t size, size_t alignment, void* user) {
  Hook& h = *static_cast<Hook*>(user);
  if (++h.allocs == h.fail_at) return nullptr;
  if (alignment > kHeader || (alignment & (alignment - 1)) != 0) return nullptr;
  auto* base = static_cast<unsigned char*>(std::aligned_alloc(kHeader, kHeader + size));
  if (base == nullptr) return nullptr;
  std::memcpy(base, &size, sizeof size);
  std::memcpy(base + sizeof size, &alignment, sizeof alignment);
  ++h.live;
  return base + kHeader;
}

void hook_free(void* p, size_t size, size_t alignment, void* user) {
  Hook& h = *static_cast<Hook*>(user);
  ++h.frees;
  if (p == nullptr) return;
  unsigned char* base = static_cast<unsigned char*>(p) - kHeader;
  std::size_t s = 0;
  std::size_t a = 0;
  std::memcpy(&s, base, sizeof s);
  std::memcpy(&a, base + sizeof s, sizeof a);
  if (s != size || a != alignment) ++h.bad_frees;
  --h.live;
  std::free(base);
}

constexpr double kDt = 1.0 / 60.0;
constexpr int kSteps = 8;
constexpr int kFragments = 240;

// A blast 6 m ahead of a walking camera, a quarter of it aimed at the lens; ids change at step 4
// (a third gone, 30 new), so steps 0 and 4 re-index and the others are steady.
std::vector<fragsim_fragment> fragments_at(int step) {
  std::vector<fragsim_fragment> out;
  const double t = 0.3 + step * kDt;
  for (int i = 0; i < kFragments; ++i) {
    if (step >= 4 && i % 3 == 1) continue;
    const double a = 2.399963 * i;
    const double z = 1.0 - 2.0 * (i + 0.5) / kFragments;
    const double r = std::sqrt(1.0 - z * z);
    fragsim_fragment f{};
    const double vx = 7.0 * r * std::cos(a), vy = 7.0 * r * std::sin(a) + 2.0, vz = 7.0 * z + 6.0;
    f.position_m = {vx * t, vy * t - 4.905 * t * t, -6.0 + vz * t};
    f.velocity_mps = {vx, vy - 9.81 * t, vz};
    if (i % 4 == 0) {  // aimed at the eye
      const double arrive = 0.2 + 0.01 * i - step * kDt;
      f.position_m = {0.05 * std::cos(1.1 * i), 0.05 * std::sin(1.1 * i), -12.0 * arrive};
      f.velocity_mps = {-f.position_m.x / arrive, -f.position_m.y / arrive + 4.905 * arrive, 12.0};
    }
    f.radius_m = 0.04 + 0.0002 * i;
    f.mass_kg = 0.3 + 0.002 * i;
    f.id = 500 + static_cast<std::uint64_t>(i);
    out.push_back(f);
  }
  if (step >= 4) {
    for (int k = 0; k < 30; ++k) {
      fragsim_fragment f = out[static_cast<std::size_t>(k)];
      f.id = 90000 + static_cast<std::uint64_t>(k);
      f.velocity_mps.x = -f.velocity_mps.x;
      out.push_back(f);
    }
  }
  return out;
}

struct Scene {
  std::vector<std::vector<fragsim_fragment>> steps;
  Scene() {
    for (int k = 0; k < kSteps; ++k) steps.push_back(fragments_at(k));
  }
  // Step k's input; its one camera's pose goes to `pose`, which must outlive the call.
  fragsim_step_input input(int k, fragsim_camera_pose& pose) const {
    fragsim_step_input in = fragsim_default_step_input();
    in.time_s = k * kDt;
    in.ground_height_m = -1.6;
    pose = fragsim_default_camera_pose();
    pose.velocity_mps = {0.0, 0.0, -1.0};
    pose.eye_m = {0.0, 0.0, -1.0 * k * kDt};
    in.camera_poses = &pose;
    in.camera_count = 1;
    return in;
  }
  const std::vector<fragsim_fragment>& fragments(int k) const {
    return steps[static_cast<std::size_t>(k)];
  }
};

using Forces = std::vector<fragsim_vec3>;

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
  d.edge_min.cover_max = 0.5;  // the occlusion bound allocates as it steps
  c.push_back({"edge-min, cover_max 0.5", d});
  d = fragsim_default_controller_def();
  d.strategy = FRAGSIM_STRATEGY_EDGE;
  c.push_back({"edge", d});
  d.strategy = FRAGSIM_STRATEGY_DEFLECT_ALL;
  c.push_back({"deflect-all", d});
  return c;
}

fragsim_controller_def hooked(fragsim_controller_def def, Hook& h) {
  def.alloc_fn = hook_alloc;
  def.free_fn = hook_free;
  def.alloc_user = &h;
  return def;
}

fragsim_status step(fragsim_controller_id c, const Scene& s, int k, Forces& out,
                    fragsim_step_stats* stats = nullptr) {
  // One camera, set before each step: setting one camera again allocates nothing and keeps the
  // fragments' state.
  const fragsim_camera_def camera = fragsim_default_camera_def();
  if (fragsim_controller_set_cameras(c, &camera, 1) != FRAGSIM_OK) return FRAGSIM_ERROR_INTERNAL;
  fragsim_camera_pose pose;
  const fragsim_step_input in = s.input(k, pose);
  const std::vector<fragsim_fragment>& f = s.fragments(k);
  out.assign(f.size(), fragsim_vec3{7.0, 7.0, 7.0});
  return fragsim_controller_step(c, &in, f.data(), static_cast<int32_t>(f.size()), out.data(),
                                 stats);
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

void half_a_hook_is_refused() {
  fragsim_controller_def def = fragsim_default_controller_def();
  fragsim_controller_id c{};
  char message[200];
  def.alloc_fn = hook_alloc;
  CHECK(fragsim_controller_create(&def, &c, message, sizeof message) ==
        FRAGSIM_ERROR_INVALID_ARGUMENT);
  CHECK(std::strstr(message, "free_fn: NULL") != nullptr);
  CHECK(fragsim_controller_id_is_null(c));
  def.alloc_fn = nullptr;
  def.free_fn = hook_free;
  CHECK(fragsim_controller_create(&def, &c, message, sizeof message) ==
        FRAGSIM_ERROR_INVALID_ARGUMENT);
  CHECK(std::strstr(message, "alloc_fn: NULL") != nullptr);
}

void check_config(const Config& cfg, const Scene& s) {
  // The reference, hookless.
  std::vector<Forces> reference(kSteps);
  int pushed = 0;
  {
    fragsim_controller_id r{};
    CHECK(fragsim_controller_create(&cfg.def, &r, nullptr, 0) == FRAGSIM_OK);
    for (int k = 0; k < kSteps; ++k) {
      CHECK(step(r, s, k, reference[static_cast<std::size_t>(k)]) == FRAGSIM_OK);
      pushed += all_zero(reference[static_cast<std::size_t>(k)]) ? 0 : 1;
    }
    fragsim_controller_destroy(r);
  }
  CHECK(pushed > 0);  // forces to compare, not zeros

  // A whole life with the hook: operator new never called, the same forces, every block back.
  {
    Hook h;
    const fragsim_controller_def def = hooked(cfg.def, h);
    fragsim_controller_id c{};
    Forces f(kFragments + 30);  // the test's own buffer, made before counting
    g_global_news = 0;
    g_watch = true;
    CHECK(fragsim_controller_create(&def, &c, nullptr, 0) == FRAGSIM_OK);
    const long after_create = h.allocs;
    CHECK(fragsim_controller_reserve(c, kFragments + 30) == FRAGSIM_OK);
    long steady_hook = -1;
    long steady_new = -1;
    for (int k = 0; k < kSteps; ++k) {
      const long hook_before = h.allocs + h.frees;
      const long new_before = g_global_news;
      CHECK(step(c, s, k, f) == FRAGSIM_OK);
      CHECK(same(f, reference[static_cast<std::size_t>(k)]));
      if (k == 2) {  // after create, reserve and one step: a steady step
        steady_hook = h.allocs + h.frees - hook_before;
        steady_new = g_global_news - new_before;
      }
    }
    CHECK(fragsim_controller_reset(c) == FRAGSIM_OK);
    CHECK(step(c, s, 0, f) == FRAGSIM_OK);
    CHECK(same(f, reference[0]));
    CHECK(fragsim_controller_destroy(c) == FRAGSIM_OK);
    g_watch = false;
    std::printf(
        "%s: %ld hook allocations (%ld at create), %ld operator new, steady step: %ld "
        "hook calls, %ld operator new\n",
        cfg.name, h.allocs, after_create, g_global_news, steady_hook, steady_new);
    CHECK(after_create > 0);
    CHECK(g_global_news == 0);
    CHECK(steady_new == 0);
    // The occlusion bound's step allocates its temporaries (through the hook): not steady.
    if (cfg.def.edge_min.cover_max >= 1.0) CHECK(steady_hook == 0);
    CHECK(h.live == 0);
    CHECK(h.bad_frees == 0);
    CHECK(h.allocs == h.frees);
  }

  // The hook fails its Nth call, for every N of a re-indexing step and of the steady step after.
  long failed_calls = 0;
  for (int k : {0, 1, 4}) {
    long total = 0;
    {
      Hook h;
      const fragsim_controller_def def = hooked(cfg.def, h);
      fragsim_controller_id c{};
      Forces f;
      CHECK(fragsim_controller_create(&def, &c, nullptr, 0) == FRAGSIM_OK);
      for (int j = 0; j < k; ++j) CHECK(step(c, s, j, f) == FRAGSIM_OK);
      const long before = h.allocs;
      CHECK(step(c, s, k, f) == FRAGSIM_OK);
      total = h.allocs - before;
      fragsim_controller_destroy(c);
    }
    for (long n = 1; n <= total; ++n) {
      Hook h;
      const fragsim_controller_def def = hooked(cfg.def, h);
      fragsim_controller_id c{};
      Forces f;
      CHECK(fragsim_controller_create(&def, &c, nullptr, 0) == FRAGSIM_OK);
      for (int j = 0; j < k; ++j) CHECK(step(c, s, j, f) == FRAGSIM_OK);
      h.fail_at = h.allocs + n;
      const fragsim_status st = step(c, s, k, f);
      h.fail_at = 0;
      ++failed_calls;
      CHECK(st == FRAGSIM_ERROR_OUT_OF_MEMORY);
      CHECK(all_zero(f));
      // As before the call: the same step again, and the next two, as if it had never failed.
      // (cover_max < 1: a failure inside the occlusion bound forgets every fragment, as the
      // header says; its retry is then a fresh controller's step, checked for success only.)
      for (int j = k; j < k + 3 && j < kSteps; ++j) {
        CHECK(step(c, s, j, f) == FRAGSIM_OK);
        if (cfg.def.edge_min.cover_max >= 1.0 && !same(f, reference[static_cast<std::size_t>(j)])) {
          std::fprintf(stderr, "%s: hook call %ld of step %d failed: step %d differs\n", cfg.name,
                       n, k, j);
          ++failures;
        }
      }
      fragsim_controller_destroy(c);
      CHECK(h.live == 0);
    }
  }

  // A create whose hook fails: out of memory, the null id, nothing kept.
  long create_calls = 0;
  {
    Hook h;
    const fragsim_controller_def def = hooked(cfg.def, h);
    fragsim_controller_id c{};
    CHECK(fragsim_controller_create(&def, &c, nullptr, 0) == FRAGSIM_OK);
    create_calls = h.allocs;
    fragsim_controller_destroy(c);
  }
  for (long n = 1; n <= create_calls; ++n) {
    Hook h;
    h.fail_at = n;
    const fragsim_controller_def def = hooked(cfg.def, h);
    fragsim_controller_id c{};
    char message[100];
    CHECK(fragsim_controller_create(&def, &c, message, sizeof message) ==
          FRAGSIM_ERROR_OUT_OF_MEMORY);
    CHECK(fragsim_controller_id_is_null(c));
    CHECK(h.live == 0);
  }
  std::printf("%s: %ld failed hook calls in steps, %ld in creates, each recovered\n", cfg.name,
              failed_calls, create_calls);
}

}  // namespace

int main() {
  // The process-wide, once-only allocations (the parameters' rule tables, the first chunk of id
  // slots) happen here, hookless, so that what follows sees a controller's own allocations only.
  {
    fragsim_controller_def def = fragsim_default_controller_def();
    fragsim_controller_id warm{};
    g_global_news = 0;
    g_watch = true;
    CHECK(fragsim_controller_create(&def, &warm, nullptr, 0) == FRAGSIM_OK);
    g_watch = false;
    std::printf("first create of the process: %ld operator new calls (hookless)\n", g_global_news);
    fragsim_controller_destroy(warm);
  }
  half_a_hook_is_refused();
  const Scene s;
  for (const Config& cfg : configs()) check_config(cfg, s);
  return check_verdict("allocator_hook_test");
}
