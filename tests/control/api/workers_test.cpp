// The controller on the game's workers: a step's forces and stats are bit for bit the same on 1, 2,
// 3 and 8 workers of the thread pool examples/thread_pool ships, and on a scheduler that runs
// uneven ranges in a shuffled order on random workers, as without a task system; a steady step
// with workers allocates nothing (counted through the def's allocator hook); a task system that
// runs a range on a worker index it did not announce, or skips items, fails the step with a
// message and forgets every fragment, never answers from a half-run step. Built under
// ThreadSanitizer too (FRAGSIM_API_TESTS_TSAN), where a data race between the workers fails it.

#include <fragsim/control.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "check.h"
#include "fragsim_thread_pool.hpp"

namespace {

constexpr double kDt = 1.0 / 60.0;
constexpr int kSteps = 24;

// An explosion 6 m in front of the camera, thrown every way, a share of it at the lens; a few
// fragments much larger than the rest, so that the largest radius changes from step to step.
std::vector<std::vector<fragsim_fragment>> make_steps(int count) {
  std::vector<fragsim_fragment> now;
  for (int i = 0; i < count; ++i) {
    fragsim_fragment f = fragsim_default_fragment();
    const double a = 2.399963 * i;
    const double z = 1.0 - 2.0 * (i + 0.5) / count;
    const double r = std::sqrt(1.0 - z * z);
    f.position_m = {0.01 * std::cos(a), 1.6 + 0.01 * std::sin(a), -6.0};
    f.velocity_mps = {5.0 * r * std::cos(a), 5.0 * r * std::sin(a) + 2.0, 5.0 * z + 7.0};
    f.radius_m = i % 97 == 0 ? 0.4 : 0.03 + 0.0001 * (i % 50);
    f.mass_kg = 0.2 + 0.001 * (i % 300);
    f.id = 5000 + static_cast<std::uint64_t>(i) * 3;
    now.push_back(f);
  }
  std::vector<std::vector<fragsim_fragment>> steps;
  for (int k = 0; k < kSteps; ++k) {
    steps.push_back(now);
    for (fragsim_fragment& f : now) {
      f.velocity_mps.y -= 9.81 * kDt;
      f.position_m.x += f.velocity_mps.x * kDt;
      f.position_m.y += f.velocity_mps.y * kDt;
      f.position_m.z += f.velocity_mps.z * kDt;
    }
    if (k == 12) now[0].radius_m = 0.9;  // larger than any before: the rejection's hint is short
  }
  return steps;
}

struct Outcome {
  fragsim_status status = FRAGSIM_OK;
  std::vector<fragsim_vec3> forces;
  fragsim_step_stats stats{};
};

bool same(const Outcome& a, const Outcome& b) {
  return a.status == b.status && a.forces.size() == b.forces.size() &&
         std::memcmp(a.forces.data(), b.forces.data(), a.forces.size() * sizeof a.forces[0]) == 0 &&
         std::memcmp(&a.stats, &b.stats, sizeof a.stats) == 0;
}

// Counts the allocations of a controller through its hook while asked.
struct Counter {
  std::atomic<long> allocations{0};
};
void* counted_alloc(size_t size, size_t alignment, void* user) {
  ++static_cast<Counter*>(user)->allocations;
  return ::operator new(size, std::align_val_t(std::max(alignment, alignof(void*))));
}
void counted_free(void* p, size_t, size_t alignment, void*) {
  ::operator delete(p, std::align_val_t(std::max(alignment, alignof(void*))));
}

struct Run {
  std::vector<Outcome> steps;
  long steady_allocations = 0;  // over steps 2 and later
};

Run run(fragsim_controller_def def, const std::vector<std::vector<fragsim_fragment>>& steps,
        int cameras) {
  Counter counter;
  def.alloc_fn = counted_alloc;
  def.free_fn = counted_free;
  def.alloc_user = &counter;
  fragsim_controller_id ctl{};
  char message[256];
  Run r;
  if (fragsim_controller_create(&def, &ctl, message, sizeof message) != FRAGSIM_OK) {
    std::fprintf(stderr, "create: %s\n", message);
    ++failures;
    return r;
  }
  fragsim_camera_def defs[2] = {fragsim_default_camera_def(), fragsim_default_camera_def()};
  CHECK(fragsim_controller_set_cameras(ctl, defs, cameras) == FRAGSIM_OK);
  fragsim_camera_pose poses[2] = {fragsim_default_camera_pose(), fragsim_default_camera_pose()};
  fragsim_step_input in = fragsim_default_step_input();
  in.ground_height_m = 0.0;
  in.camera_poses = poses;
  in.camera_count = cameras;
  for (int k = 0; k < kSteps; ++k) {
    for (int j = 0; j < cameras; ++j) {
      poses[j].eye_m = {cameras == 2 ? (j == 0 ? -0.032 : 0.032) : 0.0, 1.6, -0.5 * k * kDt};
      poses[j].velocity_mps = {0.0, 0.0, -0.5};
    }
    in.time_s = k * kDt;
    const std::vector<fragsim_fragment>& f = steps[static_cast<std::size_t>(k)];
    Outcome o;
    o.forces.assign(f.size(), fragsim_vec3{7.0, 7.0, 7.0});
    const long before = counter.allocations.load();
    o.status = fragsim_controller_step(ctl, &in, f.data(), static_cast<int32_t>(f.size()),
                                       o.forces.data(), &o.stats);
    if (k >= 2) r.steady_allocations += counter.allocations.load() - before;
    if (o.status != FRAGSIM_OK) {
      std::fprintf(stderr, "step %d: %s\n", k, fragsim_controller_last_error(ctl));
    }
    r.steps.push_back(std::move(o));
  }
  fragsim_controller_destroy(ctl);
  return r;
}

// A scheduler of the test's: every run cut at seeded random points into ranges (at least
// min_range), run in a shuffled order on random workers, on this thread.
struct Shuffled {
  std::uint64_t state = 0x9e3779b97f4a7c15u;
  int workers = 5;
  // A broken scheduler, for the refusal: a range on worker `workers`, or the last range skipped.
  bool bad_worker = false;
  bool skip_last = false;
  std::uint64_t next() {
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    return state;
  }
};

void* shuffled_enqueue(fragsim_task_fn* task, int32_t n, int32_t min_range, void* context,
                       void* user) {
  Shuffled& s = *static_cast<Shuffled*>(user);
  std::vector<std::pair<int32_t, int32_t>> ranges;
  for (int32_t begin = 0; begin < n;) {
    const int32_t end = std::min<int32_t>(
        n, begin + std::max<int32_t>(min_range, 1 + static_cast<int32_t>(s.next() % 300)));
    ranges.push_back({begin, end});
    begin = end;
  }
  for (std::size_t i = ranges.size(); i > 1; --i) std::swap(ranges[i - 1], ranges[s.next() % i]);
  if (s.skip_last) ranges.pop_back();
  for (std::size_t i = 0; i < ranges.size(); ++i) {
    const auto worker =
        static_cast<uint32_t>(s.bad_worker && i == 0 ? s.workers : s.next() % s.workers);
    task(ranges[i].first, ranges[i].second, worker, context);
  }
  return nullptr;
}
void shuffled_finish(void*, void*) {}

struct Config {
  const char* name;
  fragsim_controller_def def;
  int cameras;
};

std::vector<Config> configs() {
  std::vector<Config> c;
  fragsim_controller_def d = fragsim_default_controller_def();
  c.push_back({"edge-min", d, 1});
  c.push_back({"edge-min, two cameras", d, 2});
  d.edge_min.camera_model = FRAGSIM_CAMERA_CONSTANT;
  c.push_back({"edge-min, constant camera", d, 1});
  d.edge_min.camera_model = FRAGSIM_CAMERA_REACHABLE;
  c.push_back({"edge-min, reachable", d, 1});
  d = fragsim_default_controller_def();
  d.edge_min.max_solves = 40;
  c.push_back({"edge-min, max_solves 40", d, 1});
  d = fragsim_default_controller_def();
  d.strategy = FRAGSIM_STRATEGY_EDGE;
  c.push_back({"edge", d, 1});
  d.strategy = FRAGSIM_STRATEGY_DEFLECT_ALL;
  c.push_back({"deflect-all", d, 1});
  return c;
}

void check_config(const Config& cfg, const std::vector<std::vector<fragsim_fragment>>& steps) {
  const Run serial = run(cfg.def, steps, cfg.cameras);
  int pushed = 0;
  for (const Outcome& o : serial.steps) {
    CHECK(o.status == FRAGSIM_OK);
    pushed += o.stats.pushed;
  }
  CHECK(pushed > 0);  // the scenario reaches the forces
  for (const int workers : {1, 2, 3, 8}) {
    FragsimThreadPool pool(workers);
    fragsim_controller_def def = cfg.def;
    pool.install(def);
    const Run threaded = run(def, steps, cfg.cameras);
    bool all_same = threaded.steps.size() == serial.steps.size();
    for (std::size_t k = 0; all_same && k < serial.steps.size(); ++k) {
      all_same = same(threaded.steps[k], serial.steps[k]);
      if (!all_same) {
        std::fprintf(stderr, "%s, %d workers: step %zu differs from the calling thread's\n",
                     cfg.name, workers, k);
      }
    }
    CHECK(all_same);
    if (threaded.steady_allocations != 0) {
      std::fprintf(stderr, "%s, %d workers: %ld allocations in steady steps\n", cfg.name, workers,
                   threaded.steady_allocations);
    }
    CHECK(threaded.steady_allocations == 0);
  }
  Shuffled shuffled;
  fragsim_controller_def def = cfg.def;
  def.enqueue_task = shuffled_enqueue;
  def.finish_task = shuffled_finish;
  def.user_task_context = &shuffled;
  def.worker_count = shuffled.workers;
  const Run mixed = run(def, steps, cfg.cameras);
  bool all_same = mixed.steps.size() == serial.steps.size();
  for (std::size_t k = 0; all_same && k < serial.steps.size(); ++k) {
    all_same = same(mixed.steps[k], serial.steps[k]);
  }
  CHECK(all_same);
  std::printf(
      "%s, %d camera(s): %d pushes over %d steps, the same on 1, 2, 3, 8 and shuffled "
      "workers\n",
      cfg.name, cfg.cameras, pushed, kSteps);
}

// A task system that breaks its contract fails the step; nothing of it is answered.
void check_broken_scheduler(const std::vector<std::vector<fragsim_fragment>>& steps) {
  for (const bool bad_worker : {true, false}) {
    Shuffled s;
    s.bad_worker = bad_worker;
    s.skip_last = !bad_worker;
    fragsim_controller_def def = fragsim_default_controller_def();
    def.enqueue_task = shuffled_enqueue;
    def.finish_task = shuffled_finish;
    def.user_task_context = &s;
    def.worker_count = s.workers;
    const Run r = run(def, steps, 1);
    CHECK(r.steps[0].status == FRAGSIM_ERROR_INVALID_ARGUMENT);
    for (const fragsim_vec3& f : r.steps[0].forces) CHECK(f.x == 0.0 && f.y == 0.0 && f.z == 0.0);
  }
  fragsim_controller_def def = fragsim_default_controller_def();
  def.enqueue_task = shuffled_enqueue;
  fragsim_controller_id ctl{};
  char message[256];
  CHECK(fragsim_controller_create(&def, &ctl, message, sizeof message) ==
        FRAGSIM_ERROR_INVALID_ARGUMENT);
  CHECK(std::string(message).find("finish_task: NULL") != std::string::npos);
  def = fragsim_default_controller_def();
  def.worker_count = FRAGSIM_MAX_WORKERS + 1;
  CHECK(fragsim_controller_create(&def, &ctl, message, sizeof message) ==
        FRAGSIM_ERROR_INVALID_ARGUMENT);
  CHECK(std::string(message).find("worker_count = 65") != std::string::npos);
}

}  // namespace

int main() {
  const std::vector<std::vector<fragsim_fragment>> steps = make_steps(3000);
  for (const Config& cfg : configs()) check_config(cfg, steps);
  check_broken_scheduler(steps);
  return check_verdict("workers_test");
}
