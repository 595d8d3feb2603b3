// libFuzzer target: the controller library's C API (fragsim/control.h) as a careless engine drives
// it: random defs, cameras, fragments with NaN, infinities, huge and negative numbers, ids that
// repeat, counts out of range, masses beyond the rule's range, struct or strided-array input with
// random strides, several steps on one controller, cameras set once (none, 1 to 3 of them, or a
// count out of range; any aspect) and poses for some or all of them, allocations that fail, and a
// task system that splits each run into random ranges on random workers.
//
// Input: bytes read by FuzzedDataProvider (choices first, then numbers; missing bytes read as 0).
//
// Two controllers get the same calls: A sometimes has one allocation of a call fail (this file
// replaces operator new; the Nth allocation of the call throws) and may run on a task system of 1
// to 8 workers that runs its ranges in a shuffled order on this thread; B never fails and runs on
// the calling thread. Checks (__builtin_trap() on violation):
//  - every status is one of fragsim_status; last_error is never NULL;
//  - every force written is finite; after a failed call with a valid count, every force is 0;
//  - stats: counts within [0, count], first_skipped in [-1, count), pushed <= count;
//  - after FRAGSIM_ERROR_OUT_OF_MEMORY, A retried without a failure gives B's status and B's forces
//    bit for bit: the failure left A as it was; and without one, A's workers change no bit;
//  - a destroyed controller's id is refused (FRAGSIM_ERROR_STALE_ID), destroying it again too.

#include <fuzzer/FuzzedDataProvider.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <new>
#include <vector>

#include "../control/api/replaced_operator_new.hpp"
#include "fragsim/control.h"

namespace {

long g_allocations = 0;
long g_fail_at = 0;  // 0: none

}  // namespace

void* test_allocate(std::size_t n, std::size_t alignment) {
  if (g_fail_at != 0 && ++g_allocations == g_fail_at) throw std::bad_alloc();
  return test_system_block(n, alignment);
}

namespace {

void require(bool ok) {
  if (!ok) __builtin_trap();
}

constexpr double kInf = std::numeric_limits<double>::infinity();

// A number a careless caller might pass: special values often, else a value in a wide range.
double number(FuzzedDataProvider& in, double lo, double hi) {
  static const double special[] = {0.0,
                                   -0.0,
                                   1.0,
                                   -1.0,
                                   kInf,
                                   -kInf,
                                   std::numeric_limits<double>::quiet_NaN(),
                                   1e300,
                                   -1e300,
                                   1e-300,
                                   5e-324,
                                   1.6e-314,
                                   FRAGSIM_UNDECLARED};
  const int pick = in.ConsumeIntegralInRange<int>(0, 20);
  if (pick < static_cast<int>(sizeof special / sizeof special[0])) return special[pick];
  return in.ConsumeFloatingPointInRange<double>(lo, hi);
}

fragsim_vec3 vec(FuzzedDataProvider& in, double lo, double hi) {
  return {number(in, lo, hi), number(in, lo, hi), number(in, lo, hi)};
}

// A task system of the fuzzer's: each run split at random points into ranges, run in a shuffled
// order on random workers, all on this thread before enqueue returns (NULL: nothing to finish).
struct FuzzTasks {
  std::vector<std::uint8_t> choices;  // consumed in turn, then reused
  std::size_t next = 0;
  int workers = 1;
  std::uint8_t pick() {
    if (choices.empty()) return 0;
    const std::uint8_t c = choices[next % choices.size()];
    ++next;
    return c;
  }
};

void* fuzz_enqueue(fragsim_task_fn* task, int32_t item_count, int32_t min_range, void* context,
                   void* user) {
  FuzzTasks& t = *static_cast<FuzzTasks*>(user);
  std::vector<std::pair<int32_t, int32_t>> ranges;
  int32_t begin = 0;
  while (begin < item_count) {
    const int32_t span = std::max<int32_t>(min_range, 1 + t.pick() % 97);
    const int32_t end = std::min<int32_t>(item_count, begin + span);
    ranges.push_back({begin, end});
    begin = end;
  }
  for (std::size_t i = ranges.size(); i > 1; --i) std::swap(ranges[i - 1], ranges[t.pick() % i]);
  for (const auto& r : ranges) {
    task(r.first, r.second, static_cast<uint32_t>(t.pick() % t.workers), context);
  }
  return nullptr;
}

void fuzz_finish(void*, void*) {}

bool valid_status(fragsim_status s) {
  return static_cast<int>(s) >= FRAGSIM_OK && static_cast<int>(s) <= FRAGSIM_ERROR_STALE_ID;
}

struct Call {
  fragsim_step_input input{};
  std::vector<fragsim_fragment> fragments;
  std::vector<fragsim_camera_pose> poses;  // camera_count of them (input.camera_poses)
  bool arrays = false;
  bool floats = false;  // arrays of floats (scalar_type FRAGSIM_SCALAR_FLOAT)
  int32_t count = 0;
  // The arrays' layout: each field at its own stride (a multiple of its size) in one buffer.
  std::size_t stride = 0;
  std::vector<unsigned char> buffer;
};

Call make_call(FuzzedDataProvider& in, double time_s) {
  Call c;
  fragsim_step_input& s = c.input;
  s = fragsim_default_step_input();
  s.time_s = in.ConsumeBool() ? time_s : number(in, -10, 10);
  if (in.ConsumeBool()) s.end_time_s = number(in, -10, 10);
  if (in.ConsumeBool()) s.dt_s = number(in, 1e-6, 1.0);
  if (in.ConsumeBool()) s.gravity_mps2 = vec(in, -20, 20);
  if (in.ConsumeBool()) s.ground_height_m = number(in, -10, 10);
  if (in.ConsumeBool()) {  // an axis (exact), or any vector: mostly not unit, then refused
    const fragsim_vec3 axes[] = {{0, 0, 1}, {0, 0, -1}, {1, 0, 0}, {0, -1, 0}, {0, 0, 0}};
    const int pick = in.ConsumeIntegralInRange<int>(0, 5);
    s.ground_normal = pick < 5 ? axes[pick] : vec(in, -1, 1);
  }
  {  // the poses: often as many as the controller's cameras, sometimes not
    const int k = in.ConsumeBool() ? 1 : in.ConsumeIntegralInRange<int>(0, 4);
    for (int j = 0; j < k; ++j) {
      fragsim_camera_pose p = fragsim_default_camera_pose();
      p.eye_m = {0.064 * j, 0.0, 0.0};
      if (in.ConsumeBool()) p.eye_m = vec(in, -10, 10);
      if (in.ConsumeBool()) p.velocity_mps = vec(in, -60, 60);
      if (in.ConsumeBool()) p.up = vec(in, -1, 1);  // mostly not unit: refused
      if (in.ConsumeBool()) {                       // facing the other way, or not unit: refused
        p.forward = in.ConsumeBool() ? fragsim_vec3{0, 0, 1} : vec(in, -1, 1);
        p.right = {-1, 0, 0};
      }
      c.poses.push_back(p);
    }
    s.camera_count = in.ConsumeIntegralInRange<int>(0, 15) == 0 ? -1 : k;
    s.camera_poses =
        c.poses.empty() || in.ConsumeIntegralInRange<int>(0, 15) == 0 ? nullptr : c.poses.data();
  }
  const int n = in.ConsumeIntegralInRange<int>(0, 48);
  for (int i = 0; i < n; ++i) {
    fragsim_fragment f{};
    f.position_m = {number(in, -3, 3), number(in, -3, 3), number(in, -12, 1)};
    f.velocity_mps = {number(in, -5, 5), number(in, -5, 5), number(in, -5, 30)};
    f.radius_m = number(in, 0, 0.5);
    f.mass_kg = in.ConsumeIntegralInRange<int>(0, 7) == 0
                    ? (in.ConsumeBool() ? 3.4028234663852886e38 : number(in, 1e-30, 1e30))
                    : number(in, 0, 10);
    f.id = in.ConsumeIntegralInRange<std::uint64_t>(0, 64);  // repeats happen: refused
    f.touched = in.ConsumeIntegral<std::uint8_t>();
    c.fragments.push_back(f);
  }
  c.count = static_cast<int32_t>(n);
  if (in.ConsumeIntegralInRange<int>(0, 15) == 0) {
    c.count = in.ConsumeBool() ? -1 - in.ConsumeIntegralInRange<int32_t>(0, 5)
                               : FRAGSIM_MAX_FRAGMENTS + 1;
  }
  c.arrays = in.ConsumeBool();
  c.floats = c.arrays && in.ConsumeBool();
  if (c.floats) {
    // One record per fragment in floats: position (0), velocity (12), radius (24), mass (28),
    // id (32), touched (40), force (44, 3 floats), then 0 to 3 floats of padding (a stride that
    // keeps the id's 8-byte alignment or not: the library reads unaligned ids by copying).
    c.stride = 56 + 4 * in.ConsumeIntegralInRange<std::size_t>(0, 3);
    c.buffer.assign(c.stride * static_cast<std::size_t>(n) + 1, 0);
    for (int i = 0; i < n; ++i) {
      unsigned char* r = c.buffer.data() + c.stride * static_cast<std::size_t>(i);
      const fragsim_fragment& f = c.fragments[static_cast<std::size_t>(i)];
      const float numbers[8] = {
          static_cast<float>(f.position_m.x),   static_cast<float>(f.position_m.y),
          static_cast<float>(f.position_m.z),   static_cast<float>(f.velocity_mps.x),
          static_cast<float>(f.velocity_mps.y), static_cast<float>(f.velocity_mps.z),
          static_cast<float>(f.radius_m),       static_cast<float>(f.mass_kg)};
      std::memcpy(r, numbers, sizeof numbers);
      std::memcpy(r + 32, &f.id, sizeof(std::uint64_t));
      std::memcpy(r + 40, &f.touched, 1);
    }
  } else if (c.arrays) {
    // One record per fragment: position (0), velocity (24), radius (48), mass (56), id (64),
    // touched (72), force (80, 3 doubles), then 0 to 3 doubles of padding.
    c.stride = 104 + 8 * in.ConsumeIntegralInRange<std::size_t>(0, 3);
    c.buffer.assign(c.stride * static_cast<std::size_t>(n) + 1, 0);
    for (int i = 0; i < n; ++i) {
      unsigned char* r = c.buffer.data() + c.stride * static_cast<std::size_t>(i);
      const fragsim_fragment& f = c.fragments[static_cast<std::size_t>(i)];
      std::memcpy(r, &f.position_m, 3 * sizeof(double));
      std::memcpy(r + 24, &f.velocity_mps, 3 * sizeof(double));
      std::memcpy(r + 48, &f.radius_m, sizeof(double));
      std::memcpy(r + 56, &f.mass_kg, sizeof(double));
      std::memcpy(r + 64, &f.id, sizeof(std::uint64_t));
      std::memcpy(r + 72, &f.touched, 1);
    }
  }
  return c;
}

struct Result {
  fragsim_status status = FRAGSIM_OK;
  std::vector<double> forces;
};

Result run(fragsim_controller_id id, const Call& call_in, long fail_at) {
  Call call = call_in;  // the arrays' buffer gets the forces
  const std::size_t n = call.fragments.size();
  Result r;
  std::vector<fragsim_vec3> forces(n, fragsim_vec3{7.0, 7.0, 7.0});
  fragsim_step_stats stats;
  std::memset(&stats, 0x5a, sizeof stats);
  if (call.floats) {
    for (std::size_t i = 0; i < n; ++i) {
      const float seven[3] = {7.0f, 7.0f, 7.0f};
      std::memcpy(call.buffer.data() + call.stride * i + 44, seven, sizeof seven);
    }
    fragsim_fragment_arrays a{};
    unsigned char* base = call.buffer.data();
    a.scalar_type = FRAGSIM_SCALAR_FLOAT;
    a.position_m = base;
    a.velocity_mps = base + 12;
    a.radius_m = base + 24;
    a.mass_kg = base + 28;
    a.id = reinterpret_cast<const std::uint64_t*>(base + 32);
    a.touched = base + 40;
    a.force_N = base + 44;
    a.position_stride_bytes = a.velocity_stride_bytes = a.radius_stride_bytes = call.stride;
    a.mass_stride_bytes = a.id_stride_bytes = a.touched_stride_bytes = call.stride;
    a.force_stride_bytes = call.stride;
    g_allocations = 0;
    g_fail_at = fail_at;
    r.status = fragsim_controller_step_arrays(id, &call.input, &a, call.count, &stats);
    g_fail_at = 0;
    for (std::size_t i = 0; i < n; ++i) {
      float f[3];
      std::memcpy(f, base + call.stride * i + 44, sizeof f);
      r.forces.insert(r.forces.end(), f, f + 3);
    }
  } else if (call.arrays) {
    for (std::size_t i = 0; i < n; ++i) {
      const double seven[3] = {7.0, 7.0, 7.0};
      std::memcpy(call.buffer.data() + call.stride * i + 80, seven, sizeof seven);
    }
    fragsim_fragment_arrays a{};
    unsigned char* base = call.buffer.data();
    a.position_m = reinterpret_cast<const double*>(base);
    a.velocity_mps = reinterpret_cast<const double*>(base + 24);
    a.radius_m = reinterpret_cast<const double*>(base + 48);
    a.mass_kg = reinterpret_cast<const double*>(base + 56);
    a.id = reinterpret_cast<const std::uint64_t*>(base + 64);
    a.touched = base + 72;
    a.force_N = reinterpret_cast<double*>(base + 80);
    a.position_stride_bytes = a.velocity_stride_bytes = a.radius_stride_bytes = call.stride;
    a.mass_stride_bytes = a.id_stride_bytes = a.touched_stride_bytes = call.stride;
    a.force_stride_bytes = call.stride;
    g_allocations = 0;
    g_fail_at = fail_at;
    r.status = fragsim_controller_step_arrays(id, &call.input, &a, call.count, &stats);
    g_fail_at = 0;
    for (std::size_t i = 0; i < n; ++i) {
      double f[3];
      std::memcpy(f, base + call.stride * i + 80, sizeof f);
      r.forces.insert(r.forces.end(), f, f + 3);
    }
  } else {
    g_allocations = 0;
    g_fail_at = fail_at;
    r.status = fragsim_controller_step(
        id, &call.input, call.fragments.empty() ? nullptr : call.fragments.data(), call.count,
        forces.empty() ? nullptr : forces.data(), &stats);
    g_fail_at = 0;
    for (const fragsim_vec3& f : forces) r.forces.insert(r.forces.end(), {f.x, f.y, f.z});
  }
  require(valid_status(r.status));
  require(fragsim_controller_last_error(id) != nullptr);
  const bool count_valid = call.count >= 0 && call.count <= FRAGSIM_MAX_FRAGMENTS;
  for (const double v : r.forces) {
    require(std::isfinite(v) || (!count_valid && v == 7.0));
    if (r.status != FRAGSIM_OK && count_valid) require(v == 0.0);
  }
  if (r.status == FRAGSIM_OK) {
    const int32_t c = call.count;
    for (int32_t v :
         {stats.candidates, stats.pushed, stats.capped, stats.new_ids, stats.dropped_ids,
          stats.deferred, stats.rejected_cheaply, stats.skipped, stats.unprotected}) {
      require(v >= 0);
    }
    require(stats.pushed <= c && stats.skipped <= c && stats.rejected_cheaply <= c);
    require(stats.first_skipped >= -1 && stats.first_skipped < c);
    require((stats.skipped == 0) == (stats.first_skipped == -1));
    require(stats.below_ground >= 0 && stats.below_ground <= c);
    require((stats.below_ground == 0) == (stats.first_below_ground == -1));
    require(stats.conflicts >= 0 && stats.conflicts <= c);
    require(stats.first_conflict >= -1 && stats.first_conflict < c);
    require((stats.conflicts == 0) == (stats.first_conflict == -1));
  }
  return r;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  FuzzedDataProvider in(data, size);
  fragsim_controller_def def = fragsim_default_controller_def();
  const int strategy = in.ConsumeIntegralInRange<int>(0, 3);  // 3: not a strategy
  std::memcpy(&def.strategy, &strategy, sizeof strategy);
  if (in.ConsumeBool()) def.edge_min.margin_m = number(in, 0, 1);
  if (in.ConsumeBool()) def.edge_min.a_max_mps2 = number(in, 0, 500);
  if (in.ConsumeBool()) def.edge_min.max_solves = in.ConsumeIntegralInRange<int32_t>(-1, 8);
  if (in.ConsumeBool()) def.edge_min.cover_max = number(in, 0, 1);
  if (in.ConsumeBool()) {
    const int model = in.ConsumeIntegralInRange<int>(0, 3);
    std::memcpy(&def.edge_min.camera_model, &model, sizeof model);
  }
  if (in.ConsumeBool()) def.edge.replan = FRAGSIM_EDGE_REPLAN_ALWAYS;
  if (in.ConsumeBool()) def.horizon_cap_s = number(in, 0, 10);
  fragsim_controller_def def_a = def;
  FuzzTasks tasks;
  if (in.ConsumeBool()) {
    tasks.workers = in.ConsumeIntegralInRange<int>(1, 8);
    tasks.choices = in.ConsumeBytes<std::uint8_t>(in.ConsumeIntegralInRange<int>(1, 16));
    def_a.enqueue_task = fuzz_enqueue;
    def_a.finish_task = fuzz_finish;
    def_a.user_task_context = &tasks;
    def_a.worker_count = tasks.workers;
  }
  fragsim_controller_id a{};
  fragsim_controller_id b{};
  char message[128];
  const fragsim_status created = fragsim_controller_create(&def_a, &a, message, sizeof message);
  require(valid_status(created));
  if (created != FRAGSIM_OK) {
    require(fragsim_controller_id_is_null(a) && message[0] != '\0');
    return 0;
  }
  require(fragsim_controller_create(&def, &b, nullptr, 0) == FRAGSIM_OK);
  if (in.ConsumeBool()) {
    const int32_t room = in.ConsumeIntegralInRange<int32_t>(-2, 64);
    require(fragsim_controller_reserve(a, room) == fragsim_controller_reserve(b, room));
  }
  if (in.ConsumeIntegralInRange<int>(0, 7) != 0) {  // cameras set once (else every step is
                                                    // refused); a failed allocation leaves A as B
    const int k = in.ConsumeIntegralInRange<int>(0, 15) == 0 ? FRAGSIM_MAX_CAMERAS + 1
                                                             : in.ConsumeIntegralInRange<int>(1, 3);
    std::vector<fragsim_camera_def> defs(static_cast<std::size_t>(std::max(k, 1)),
                                         fragsim_default_camera_def());
    for (fragsim_camera_def& d : defs) {
      if (in.ConsumeBool()) d.fovy_deg = number(in, 0, 180);
      if (in.ConsumeBool()) d.near_m = number(in, 0, 2);
      if (in.ConsumeBool()) d.body_half_m = vec(in, 0, 1);
      if (in.ConsumeBool()) d.max_speed_mps = number(in, 0, 100);
      if (in.ConsumeBool()) d.max_turn_degps = number(in, 0, 1000);
      if (in.ConsumeBool()) {  // any aspect, on a log scale: the occlusion bound's grid follows it
        d.aspect = std::pow(10.0, in.ConsumeFloatingPointInRange<double>(-13.0, 4.0));
      }
    }
    const fragsim_status sb = fragsim_controller_set_cameras(b, defs.data(), k);
    g_allocations = 0;
    g_fail_at = in.ConsumeBool() ? in.ConsumeIntegralInRange<long>(1, 8) : 0;
    fragsim_status sa = fragsim_controller_set_cameras(a, defs.data(), k);
    g_fail_at = 0;
    require(valid_status(sa) && valid_status(sb));
    if (sa == FRAGSIM_ERROR_OUT_OF_MEMORY) sa = fragsim_controller_set_cameras(a, defs.data(), k);
    require(sa == sb);
  }
  const int steps = in.ConsumeIntegralInRange<int>(1, 6);
  for (int k = 0; k < steps && in.remaining_bytes() > 0; ++k) {
    const Call call = make_call(in, k / 60.0);
    const long fail_at = in.ConsumeBool() ? in.ConsumeIntegralInRange<long>(1, 40) : 0;
    const Result rb = run(b, call, 0);
    Result ra = run(a, call, fail_at);
    if (ra.status == FRAGSIM_ERROR_OUT_OF_MEMORY && rb.status != FRAGSIM_ERROR_OUT_OF_MEMORY) {
      ra = run(a, call, 0);  // as before the failed call: the same answer as B's
    }
    require(ra.status == rb.status);
    require(ra.forces.size() == rb.forces.size());
    require(ra.forces.empty() || std::memcmp(ra.forces.data(), rb.forces.data(),
                                             ra.forces.size() * sizeof(double)) == 0);
    if (in.ConsumeIntegralInRange<int>(0, 9) == 0) {
      require(fragsim_controller_reset(a) == FRAGSIM_OK &&
              fragsim_controller_reset(b) == FRAGSIM_OK);
    }
  }
  require(fragsim_controller_destroy(a) == FRAGSIM_OK);
  require(fragsim_controller_destroy(a) == FRAGSIM_ERROR_STALE_ID);
  fragsim_step_input none = fragsim_default_step_input();
  require(fragsim_controller_step(a, &none, nullptr, 0, nullptr, nullptr) ==
          FRAGSIM_ERROR_STALE_ID);
  require(fragsim_controller_destroy(b) == FRAGSIM_OK);
  return 0;
}
