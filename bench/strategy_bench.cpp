// The cost of the strategies' per-step work: the thesis's prediction per
// fragment at t = 0, with and without the cheap rejection, on an aimed blast (front.ini) and on
// undirected ones; and one whole step of `edge` and `edge-min` at t = 0 and at a later step.
// Run: build/release/bench/fragsim_bench --benchmark_filter='Predict|StrategyStep|BM_Run'
// --benchmark_repetitions=5 --benchmark_report_aggregates_only

#include <benchmark/benchmark.h>
#include <time.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "control/strategies/collision_prediction.hpp"
#include "control/strategies/edge_min_strategy.hpp"
#include "control/strategies/edge_strategy.hpp"
#include "sim/explosion.hpp"
#include "sim/run.hpp"
#include "sim/scene_file.hpp"
#include "strategies/scene_strategy.hpp"

namespace {

using fragsim::FragmentState;
using fragsim::Scene;

enum class SceneKind { kAimed, kUndirected, kThesis1000 };

// The aimed default scene; the same cube blown up without the push toward the camera; and the
// thesis's 1000-fragment scene (fig. 4.3).
Scene scene_of(SceneKind kind, int splits = 0) {
  Scene s =
      fragsim::load_scene(kind == SceneKind::kThesis1000 ? FRAGSIM_DATA_DIR "/scenes/thesis1000.ini"
                                                         : FRAGSIM_DATA_DIR "/scenes/front.ini");
  if (kind == SceneKind::kUndirected) s.explosion.toward_camera_mps = 0.0;
  if (splits > 0) s.object.splits = splits;
  return s;
}

// What `edge` asks of each fragment at t = 0 (edge_strategy.cpp): the path, t_G and the contact
// with the reachable ball, for all fragments of the scene or for those the exact solve calls
// candidates or not. `exact` runs the solve alone, without the cheap rejection.
fragsim::ContactQuery query_at_start(const Scene& scene) {
  fragsim::ContactQuery q;
  q.camera_m = scene.camera.waypoints_m.front();
  q.gravity_mps2 = scene.sim.gravity_mps2;
  q.predictor = scene.strategies.edge.predictor;
  q.dt_s = scene.sim.dt_s;
  q.y_ref_m = scene.strategies.edge.horizon == fragsim::Horizon::kCamera ? q.camera_m.y()
                                                                         : scene.ground.height_m;
  q.remaining_s = scene.sim.duration_s;
  q.reach = scene.strategies.edge.reach;
  q.max_speed_mps = scene.camera.max_speed_mps;
  q.body_radius_m = (0.5 * scene.camera.body_size_m).norm();
  return q;
}

std::vector<FragmentState> fragments_at_start(const Scene& scene) {
  std::vector<FragmentState> out;
  for (const auto& sp : fragsim::explode(scene)) {
    FragmentState f;
    f.position_m = sp.position_m;
    f.velocity_mps = sp.velocity_mps;
    f.radius_m = sp.half_extents_m.norm();  // the box's bounding sphere, as the world sets it
    out.push_back(f);
  }
  return out;
}

bool exact_candidate(const fragsim::ContactQuery& q, const FragmentState& f) {
  const fragsim::BallisticPath p = q.path(f);
  return fragsim::solve_contact(p, q.camera_m, q.model(f), q.t_horizon_s(p)).candidate;
}

enum class Subset { kAll, kRejected, kCandidates };

// ns per fragment over the chosen subset (classified by the exact solve).
void BM_Predict(benchmark::State& state, SceneKind kind, Subset subset, bool exact) {
  const Scene scene = scene_of(kind);
  const fragsim::ContactQuery query = query_at_start(scene);
  const std::vector<FragmentState> fragments = fragments_at_start(scene);
  std::vector<int> which;
  int true_candidates = 0;
  for (std::size_t i = 0; i < fragments.size(); ++i) {
    const bool c = exact_candidate(query, fragments[i]);
    true_candidates += c ? 1 : 0;
    if (subset == Subset::kAll || (subset == Subset::kCandidates) == c) {
      which.push_back(static_cast<int>(i));
    }
  }
  if (which.empty()) {
    state.SkipWithError("empty subset");
    return;
  }
  fragsim::ContactPredictor predictor;
  int candidates = 0;
  for (auto _ : state) {
    candidates = 0;
    if (exact) {
      for (int i : which)
        candidates += exact_candidate(query, fragments[static_cast<std::size_t>(i)]);
    } else {
      for (const auto& p : predictor.predict(query, fragments, which)) candidates += p.candidate;
    }
    benchmark::DoNotOptimize(candidates);
  }
  const auto n = static_cast<double>(which.size());
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(which.size()));
  state.counters["fragments"] = n;
  state.counters["candidates"] = candidates;
  state.counters["true_candidates_of_all"] = true_candidates;
  state.counters["all_fragments"] = static_cast<double>(fragments.size());
  state.counters["s_per_fragment"] = benchmark::Counter(
      n, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

#define PREDICT_BENCH(scene_kind, name)                                                           \
  BENCHMARK_CAPTURE(BM_Predict, name##_all_rejection, scene_kind, Subset::kAll, false);           \
  BENCHMARK_CAPTURE(BM_Predict, name##_all_exact, scene_kind, Subset::kAll, true);                \
  BENCHMARK_CAPTURE(BM_Predict, name##_rejected_rejection, scene_kind, Subset::kRejected, false); \
  BENCHMARK_CAPTURE(BM_Predict, name##_rejected_exact, scene_kind, Subset::kRejected, true);      \
  BENCHMARK_CAPTURE(BM_Predict, name##_candidates_rejection, scene_kind, Subset::kCandidates,     \
                    false);                                                                       \
  BENCHMARK_CAPTURE(BM_Predict, name##_candidates_exact, scene_kind, Subset::kCandidates, true)

PREDICT_BENCH(SceneKind::kAimed, aimed_front);
PREDICT_BENCH(SceneKind::kUndirected, undirected_front);
PREDICT_BENCH(SceneKind::kThesis1000, thesis1000);

// One step of a strategy as a run takes it at step `at`: the run is stepped up to it, then each
// benchmark iteration steps a fresh copy of the strategy as it was then on the context the run
// gives that step.
template <class S>
void BM_StrategyStep(benchmark::State& state, S strategy) {
  const int splits = static_cast<int>(state.range(0));
  const int at = static_cast<int>(state.range(1));
  fragsim::LibraryStrategyRef ref(strategy);
  fragsim::Run run(scene_of(SceneKind::kAimed, splits), ref);
  while (run.state().step < at) run.step();
  const S saved = strategy;
  std::vector<FragmentState> states(run.state().fragments.begin(), run.state().fragments.end());
  fragsim::StepContext ctx = run.next_context();
  ctx.fragments = states;
  // Step `at` too, so the physics time below covers steps 0 to `at`.
  run.step();
  const fragsim::RunTotals totals = run.totals();
  fragsim::StepOutput out;
  std::size_t candidates = 0;
  for (auto _ : state) {
    // A fresh copy of the strategy as it was before the step (edge's candidates), not timed.
    state.PauseTiming();
    S s = saved;
    out.clear();
    state.ResumeTiming();
    s.step(ctx, out);
    candidates = out.activity.candidates.size();
    benchmark::DoNotOptimize(out.forces.data());
  }
  state.counters["fragments"] = static_cast<double>(ctx.fragments.size());
  state.counters["candidates"] = static_cast<double>(candidates);
  state.counters["forces"] = static_cast<double>(out.forces.size());
  // The physics of the run's steps, for a ratio measured in the same process.
  state.counters["physics_ms_per_step"] = 1e3 * totals.physics_s / totals.steps;
}

void strategy_args(benchmark::internal::Benchmark* b) {
  for (int splits : {12, 25}) {
    for (int at : {0, 30}) b->Args({splits, at});
  }
  b->ArgNames({"splits", "step"})->Unit(benchmark::kMicrosecond);
}

BENCHMARK_CAPTURE(BM_StrategyStep, edge,
                  fragsim::EdgeStrategy(scene_of(SceneKind::kAimed).strategies.edge))
    ->Apply(strategy_args);
BENCHMARK_CAPTURE(BM_StrategyStep, edge_min,
                  fragsim::EdgeMinStrategy(scene_of(SceneKind::kAimed).strategies.edge_min))
    ->Apply(strategy_args);

}  // namespace

// A strategy's steps over a whole run, replayed: the run is stepped once with the strategy,
// every step's context kept, then each iteration steps a fresh strategy through all of them. The
// statistic reported is this time over the run's physics time (the counter physics_ms, the
// same process): the strategy's share of the physics step over the run. The forces' checksum
// counter shows a change to the strategy's code left its output as it was.
double thread_cpu_ms() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return 1e3 * static_cast<double>(ts.tv_sec) + 1e-6 * static_cast<double>(ts.tv_nsec);
}

template <class S>
void BM_StrategyRun(benchmark::State& state, S strategy) {
  const Scene scene = scene_of(SceneKind::kAimed, static_cast<int>(state.range(0)));
  const S fresh = strategy;
  // Every step's context as the run gives it, pointing at a copy of that step's states.
  std::vector<fragsim::StepContext> contexts;
  std::vector<std::vector<FragmentState>> states;
  const double run_start_ms = thread_cpu_ms();
  fragsim::LibraryStrategyRef ref(strategy);
  fragsim::Run run(scene, ref);
  while (!run.done()) {
    contexts.push_back(run.next_context());
    states.emplace_back(run.state().fragments.begin(), run.state().fragments.end());
    run.step();
  }
  const fragsim::RunTotals totals = run.finish();
  // The run's thread CPU time: physics, the strategy once and the copies kept; the physics' share
  // of it is run_cpu_ms less this benchmark's time (a shared machine inflates the run's
  // wall-clock physics_ms, not its CPU time).
  const double run_cpu_ms = thread_cpu_ms() - run_start_ms;
  for (std::size_t k = 0; k < contexts.size(); ++k) contexts[k].fragments = states[k];
  const int n = static_cast<int>(contexts.front().fragments.size());
  fragsim::StepOutput out;
  // FNV-1a over the forces' bytes: 32 bits, exact in a double counter.
  std::uint32_t checksum = 2166136261u;
  const auto mix = [&checksum](const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t b = 0; b < size; ++b) checksum = (checksum ^ bytes[b]) * 16777619u;
  };
  // Each step reads its states from one buffer, as a run reads the world's (warm in the cache),
  // filled and hashed outside the timing.
  std::vector<FragmentState> buffer;
  for (auto _ : state) {
    state.PauseTiming();
    S s = fresh;
    s.reset(n);
    checksum = 2166136261u;
    for (const fragsim::StepContext& run_ctx : contexts) {
      buffer.assign(run_ctx.fragments.begin(), run_ctx.fragments.end());
      fragsim::StepContext ctx = run_ctx;
      ctx.fragments = buffer;
      out.clear();
      state.ResumeTiming();
      s.step(ctx, out);
      state.PauseTiming();
      for (const fragsim::AppliedForce& f : out.forces) {
        mix(&f.fragment, sizeof f.fragment);
        mix(f.force_N.data(), 3 * sizeof(double));
      }
    }
    state.ResumeTiming();
    benchmark::DoNotOptimize(checksum);
  }
  state.counters["steps"] = static_cast<double>(contexts.size());
  state.counters["physics_ms"] = 1e3 * totals.physics_s;
  state.counters["run_cpu_ms"] = run_cpu_ms;
  state.counters["checksum"] = checksum;
}

BENCHMARK_CAPTURE(BM_StrategyRun, edge,
                  fragsim::EdgeStrategy(scene_of(SceneKind::kAimed).strategies.edge))
    ->Arg(12)
    ->ArgName("splits")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_StrategyRun, edge_min,
                  fragsim::EdgeMinStrategy(scene_of(SceneKind::kAimed).strategies.edge_min))
    ->Arg(12)
    ->ArgName("splits")
    ->Unit(benchmark::kMillisecond);
