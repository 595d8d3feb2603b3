// Whole runs of the default scene per strategy, and the prediction at t = 0 per fragment.
// Run: build/release/bench/fragsim_bench --benchmark_repetitions=5
// --benchmark_report_aggregates_only

#include <benchmark/benchmark.h>

#include "sim/explosion.hpp"
#include "sim/scene_file.hpp"
#include "sim/simulation.hpp"
#include "strategies/collision_prediction.hpp"
#include "strategies/registry.hpp"

namespace {

fragsim::Scene default_scene() {
  return fragsim::load_scene(FRAGSIM_DATA_DIR "/scenes/front.ini");
}

void BM_Run(benchmark::State& state, const char* strategy) {
  const fragsim::Scene scene = default_scene();
  auto s = fragsim::make_strategy(strategy, scene);
  for (auto _ : state) {
    const auto totals = fragsim::simulate(scene, *s);
    benchmark::DoNotOptimize(totals.steps);
    state.counters["physics_ms_per_step"] = 1e3 * totals.physics_s / totals.steps;
    state.counters["strategy_ms_per_step"] = 1e3 * totals.strategy_s / totals.steps;
  }
}
BENCHMARK_CAPTURE(BM_Run, none, "none")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Run, edge, "edge")->Unit(benchmark::kMillisecond);

// The thesis's prediction at t = 0 for every fragment of the default scene.
void BM_PredictAll(benchmark::State& state) {
  const fragsim::Scene scene = default_scene();
  const auto spawns = fragsim::explode(scene);
  const Eigen::Vector3d eye = scene.camera.waypoints_m.front();
  int candidates = 0;
  for (auto _ : state) {
    candidates = 0;
    for (const auto& sp : spawns) {
      fragsim::FragmentState f;
      f.position_m = sp.position_m;
      f.velocity_mps = sp.velocity_mps;
      const auto path = fragsim::predicted_path(f, scene.sim.gravity_mps2,
                                                fragsim::Predictor::kThesis, scene.sim.dt_s);
      const double tg = fragsim::time_to_horizon(path, eye.y(), scene.sim.duration_s);
      const fragsim::ReachModel reach{fragsim::Reach::kThesis, scene.camera.max_speed_mps, 0.3};
      candidates += fragsim::predict_contact(path, eye, reach, tg).candidate ? 1 : 0;
    }
    benchmark::DoNotOptimize(candidates);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(spawns.size()));
  state.counters["candidates"] = candidates;
}
BENCHMARK(BM_PredictAll);

}  // namespace
