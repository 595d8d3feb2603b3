// The controller library's per-step cost: one fragsim_controller_step through
// the C API, the way a game calls it, at 1,728, 15,625 and 100,000 fragments (front.ini's aimed
// blast at splits 12, 25 and 47, the last cut to 100,000), in flight (0.3 s after the explosion,
// moved on their ballistic paths) and with 90% of them resting on the ground (zero velocity,
// touched); the same with every id new at each call (the explosion's step), and a new controller's
// first call with and without fragsim_controller_reserve. Counters: s_per_fragment (shown in ns),
// the share the cheap rejection settles (edge-min: the step's own rejected_cheaply, both boxes over
// each fragment's own look-ahead; deflect-all: fragments out of range or receding), and the
// candidates and pushes of the step. The first call (every id new) is made before timing: the loop
// measures the steady state. Run: build/release/bench/fragsim_bench --benchmark_filter=Control
// --benchmark_repetitions=3
//      --benchmark_report_aggregates_only

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "control/strategies/edge_min_strategy.hpp"
#include "fragsim/control.h"
#include "sim/camera_motion.hpp"
#include "sim/explosion.hpp"
#include "sim/scene_file.hpp"

namespace {

constexpr double kInFlightAt_s = 0.3;

struct Setup {
  fragsim_step_input input{};
  fragsim_camera_def camera{};
  fragsim_camera_pose camera_pose{};
  std::vector<fragsim_fragment> fragments;
  fragsim::CameraPose pose;
  Eigen::Vector3d camera_velocity_mps = Eigen::Vector3d::Zero();
};

// A controller with the setup's camera set.
fragsim_status create(const fragsim_controller_def& def, const Setup& s,
                      fragsim_controller_id& ctl) {
  const fragsim_status st = fragsim_controller_create(&def, &ctl, nullptr, 0);
  if (st != FRAGSIM_OK) return st;
  return fragsim_controller_set_cameras(ctl, &s.camera, 1);
}

fragsim_status step(fragsim_controller_id ctl, const Setup& s, const fragsim_fragment* fragments,
                    fragsim_vec3* forces, fragsim_step_stats* stats) {
  fragsim_step_input in = s.input;  // the pose's address is the setup's, which may have moved
  in.camera_poses = &s.camera_pose;
  in.camera_count = 1;
  return fragsim_controller_step(ctl, &in, fragments, static_cast<int32_t>(s.fragments.size()),
                                 forces, stats);
}

fragsim_vec3 vec(const Eigen::Vector3d& v) {
  return {v.x(), v.y(), v.z()};
}

Setup make_setup(int count, bool resting) {
  fragsim::Scene scene = fragsim::load_scene(FRAGSIM_DATA_DIR "/scenes/front.ini");
  scene.object.splits = count <= 1728 ? 12 : count <= 15625 ? 25 : 47;
  const auto motion = fragsim::make_camera_motion(scene);
  const Eigen::Vector3d g = scene.sim.gravity_mps2;
  const double t = kInFlightAt_s;
  Setup s;
  const auto spawned = fragsim::explode(scene, *motion);
  for (std::size_t i = 0; i < spawned.size() && static_cast<int>(i) < count; ++i) {
    fragsim_fragment f{};
    const double r = spawned[i].half_extents_m.norm();
    Eigen::Vector3d p = spawned[i].position_m + spawned[i].velocity_mps * t + 0.5 * g * t * t;
    Eigen::Vector3d v = spawned[i].velocity_mps + g * t;
    // 9 of every 10 at rest on the ground when asked.
    if (resting && i % 10 != 0) {
      p.y() = scene.ground.height_m + r;
      v.setZero();
      f.touched = 1;
    }
    f.position_m = vec(p);
    f.velocity_mps = vec(v);
    f.radius_m = r;
    f.mass_kg = spawned[i].mass_kg;
    f.id = 1000 + i;
    s.fragments.push_back(f);
  }
  s.pose = motion->pose_at(t);
  s.camera_velocity_mps = motion->velocity_at(t);
  fragsim_step_input& in = s.input;
  in.time_s = t;
  in.end_time_s = INFINITY;
  in.dt_s = scene.sim.dt_s;
  in.gravity_mps2 = vec(g);
  in.ground_height_m = scene.ground.height_m;
  in.ground_normal = {0.0, 1.0, 0.0};  // the tool's world is y-up
  s.camera = fragsim_default_camera_def();
  s.camera.fovy_deg = s.pose.fovy_deg;
  s.camera.aspect = s.pose.aspect;
  s.camera.near_m = s.pose.near_m;
  s.camera.far_m = s.pose.far_m;
  s.camera.body_half_m = vec(0.5 * scene.camera.body_size_m);
  s.camera.max_speed_mps = scene.camera.max_speed_mps;
  s.camera_pose.eye_m = vec(s.pose.eye_m);
  s.camera_pose.right = vec(s.pose.right);
  s.camera_pose.up = vec(s.pose.up);
  s.camera_pose.forward = vec(s.pose.forward);
  s.camera_pose.velocity_mps = vec(s.camera_velocity_mps);
  return s;
}
// The tool's fragment states for the setup's fragments (the C API makes the same copy).
std::vector<fragsim::FragmentState> states_of(const Setup& s) {
  std::vector<fragsim::FragmentState> states;
  for (const fragsim_fragment& f : s.fragments) {
    fragsim::FragmentState st;
    st.position_m = {f.position_m.x, f.position_m.y, f.position_m.z};
    st.velocity_mps = {f.velocity_mps.x, f.velocity_mps.y, f.velocity_mps.z};
    st.radius_m = f.radius_m;
    st.mass_kg = f.mass_kg;
    st.touched = f.touched != 0;
    states.push_back(st);
  }
  return states;
}

void BM_ControlStep(benchmark::State& state, fragsim_strategy strategy, bool resting) {
  const Setup s = make_setup(static_cast<int>(state.range(0)), resting);
  fragsim_controller_def def = fragsim_default_controller_def();
  def.strategy = strategy;
  fragsim_controller_id ctl{};
  if (create(def, s, ctl) != FRAGSIM_OK) {
    state.SkipWithError("create failed");
    return;
  }
  std::vector<fragsim_vec3> forces(s.fragments.size());
  fragsim_step_stats stats{};
  // The first call sees every id for the first time (the id table fills): not the steady state.
  if (step(ctl, s, s.fragments.data(), forces.data(), &stats) != FRAGSIM_OK) {
    state.SkipWithError(fragsim_controller_last_error(ctl));
    fragsim_controller_destroy(ctl);
    return;
  }
  for (auto _ : state) {
    step(ctl, s, s.fragments.data(), forces.data(), &stats);
    benchmark::DoNotOptimize(forces.data());
    benchmark::ClobberMemory();
  }
  fragsim_controller_destroy(ctl);
  const auto n = static_cast<double>(s.fragments.size());
  state.counters["fragments"] = n;
  state.counters["s_per_fragment"] = benchmark::Counter(
      n, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  state.counters["candidates"] = stats.candidates;
  state.counters["pushed"] = stats.pushed;
  state.counters["rejected_cheaply_share"] =
      strategy == FRAGSIM_STRATEGY_EDGE_MIN ? stats.rejected_cheaply / n : 1.0 - stats.pushed / n;
}

// The explosion's step: every id new. Each iteration hands the same fragments under ids the
// controller has not seen (two id sets taken in turn, so each call drops the last call's ids and
// meets new ones): the id tables refill and the strategy's per-id state is re-indexed. Compare
// with BM_ControlStep, the same inputs with the same ids.
void BM_ControlStepAllNewIds(benchmark::State& state, bool resting) {
  Setup s = make_setup(static_cast<int>(state.range(0)), resting);
  const fragsim_controller_def def = fragsim_default_controller_def();
  fragsim_controller_id ctl{};
  if (create(def, s, ctl) != FRAGSIM_OK) {
    state.SkipWithError("create failed");
    return;
  }
  std::vector<fragsim_vec3> forces(s.fragments.size());
  const auto n = static_cast<std::uint64_t>(s.fragments.size());
  std::vector<fragsim_fragment> other = s.fragments;
  for (fragsim_fragment& f : other) f.id += n;
  step(ctl, s, s.fragments.data(), forces.data(), nullptr);
  bool flip = false;
  fragsim_step_stats stats{};
  for (auto _ : state) {
    step(ctl, s, flip ? s.fragments.data() : other.data(), forces.data(), &stats);
    flip = !flip;
    benchmark::DoNotOptimize(forces.data());
    benchmark::ClobberMemory();
  }
  fragsim_controller_destroy(ctl);
  state.counters["new_ids"] = stats.new_ids;
  state.counters["s_per_fragment"] =
      benchmark::Counter(static_cast<double>(n), benchmark::Counter::kIsIterationInvariantRate |
                                                     benchmark::Counter::kInvert);
}

// A new controller's first call (its work space grows), with or without
// fragsim_controller_reserve beforehand (the reserve itself untimed, as a game makes it at load).
void BM_ControlFirstCall(benchmark::State& state, bool reserve) {
  const Setup s = make_setup(static_cast<int>(state.range(0)), false);
  const fragsim_controller_def def = fragsim_default_controller_def();
  std::vector<fragsim_vec3> forces(s.fragments.size());
  for (auto _ : state) {
    state.PauseTiming();
    fragsim_controller_id ctl{};
    create(def, s, ctl);
    if (reserve) fragsim_controller_reserve(ctl, static_cast<int32_t>(s.fragments.size()));
    state.ResumeTiming();
    step(ctl, s, s.fragments.data(), forces.data(), nullptr);
    benchmark::DoNotOptimize(forces.data());
    state.PauseTiming();
    fragsim_controller_destroy(ctl);
    state.ResumeTiming();
  }
}

// edge-min's own step on the same inputs, without the C API (validation, copy into the tool's
// fragment states, id check, force scatter): what the boundary costs.
void BM_ControlEdgeMinDirect(benchmark::State& state, bool resting) {
  const Setup s = make_setup(static_cast<int>(state.range(0)), resting);
  std::vector<fragsim::FragmentState> states = states_of(s);
  fragsim::StepContext ctx;
  ctx.t_s = s.input.time_s;
  ctx.dt_s = s.input.dt_s;
  ctx.end_time_s = s.input.end_time_s;
  ctx.camera = s.pose;
  ctx.camera_velocity_mps = s.camera_velocity_mps;
  ctx.camera_max_speed_mps = s.camera.max_speed_mps;
  ctx.camera_max_accel_mps2 = INFINITY;
  ctx.camera_max_turn_degps = INFINITY;
  ctx.camera_body_half_m = {s.camera.body_half_m.x, s.camera.body_half_m.y, s.camera.body_half_m.z};
  ctx.gravity_mps2 = {s.input.gravity_mps2.x, s.input.gravity_mps2.y, s.input.gravity_mps2.z};
  ctx.ground_height_m = s.input.ground_height_m;
  ctx.fragments = states;
  fragsim::EdgeMinStrategy strategy{fragsim::EdgeMinParams{}};
  fragsim::StepOutput out;
  strategy.step(ctx, out);
  for (auto _ : state) {
    out.clear();
    strategy.step(ctx, out);
    benchmark::DoNotOptimize(out.forces.data());
  }
  const auto n = static_cast<double>(states.size());
  state.counters["fragments"] = n;
  state.counters["s_per_fragment"] = benchmark::Counter(
      n, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void sizes(benchmark::internal::Benchmark* b) {
  for (int n : {1728, 15625, 100000}) b->Arg(n);
  b->Unit(benchmark::kMicrosecond);
}

BENCHMARK_CAPTURE(BM_ControlStep, edge_min_in_flight, FRAGSIM_STRATEGY_EDGE_MIN, false)
    ->Apply(sizes);
BENCHMARK_CAPTURE(BM_ControlStep, edge_min_resting, FRAGSIM_STRATEGY_EDGE_MIN, true)->Apply(sizes);
BENCHMARK_CAPTURE(BM_ControlStep, deflect_all_in_flight, FRAGSIM_STRATEGY_DEFLECT_ALL, false)
    ->Apply(sizes);
BENCHMARK_CAPTURE(BM_ControlStep, deflect_all_resting, FRAGSIM_STRATEGY_DEFLECT_ALL, true)
    ->Apply(sizes);
BENCHMARK_CAPTURE(BM_ControlStepAllNewIds, edge_min_in_flight, false)->Apply(sizes);
BENCHMARK_CAPTURE(BM_ControlStepAllNewIds, edge_min_resting, true)->Apply(sizes);
BENCHMARK_CAPTURE(BM_ControlFirstCall, edge_min, false)->Arg(15625)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_ControlFirstCall, edge_min_reserved, true)
    ->Arg(15625)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_ControlEdgeMinDirect, in_flight, false)->Apply(sizes);
BENCHMARK_CAPTURE(BM_ControlEdgeMinDirect, resting, true)->Apply(sizes);

}  // namespace
