// Whole runs of the default scene per strategy (the prediction per fragment and one strategy
// step are in strategy_bench.cpp).
// Run: build/release/bench/fragsim_bench --benchmark_repetitions=5
// --benchmark_report_aggregates_only

#include <benchmark/benchmark.h>

#include "sim/scene_file.hpp"
#include "sim/scene_strategies.hpp"
#include "sim/simulation.hpp"

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
BENCHMARK_CAPTURE(BM_Run, edge_min, "edge-min")->Unit(benchmark::kMillisecond);

}  // namespace
