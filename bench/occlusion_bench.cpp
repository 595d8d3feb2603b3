// The occlusion metric's cost per step: the default scene's object (12^3 cubes of 0.1 m around
// (0, 1.6, -8)) scattered as after an explosion aimed at the camera, seen on the default 160 x 90
// grid. Run: build/release/bench/fragsim_bench --benchmark_filter=Occlusion
// --benchmark_repetitions=5

#include <benchmark/benchmark.h>

#include <Eigen/Geometry>
#include <random>
#include <vector>

#include "metrics/occlusion_metric.hpp"

namespace {

using fragsim::FragmentState;

Eigen::Vector3d draw3(std::mt19937& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(lo, hi);
  const double x = u(rng);
  const double y = u(rng);
  return {x, y, u(rng)};
}

void BM_OcclusionObserve(benchmark::State& state) {
  std::mt19937 rng(11);
  const int n = static_cast<int>(state.range(0));
  std::vector<FragmentState> frags(static_cast<std::size_t>(n));
  for (FragmentState& f : frags) {
    f.position_m = draw3(rng, -1.0, 1.0).cwiseProduct(Eigen::Vector3d(3.0, 2.0, 4.0)) +
                   Eigen::Vector3d(0.0, 1.6, -4.5);
    f.half_extents_m = Eigen::Vector3d::Constant(0.049);
    const Eigen::Vector3d axis = draw3(rng, -1.0, 1.0);
    f.rotation = Eigen::AngleAxisd(3.0 * axis.norm(), axis.normalized()).toRotationMatrix();
    f.radius_m = f.half_extents_m.norm();
  }
  fragsim::StepSnapshot snap;
  snap.camera.eye_m = Eigen::Vector3d(0, 1.6, 0);
  snap.fragments = frags;
  fragsim::RunInfo info;
  info.fragment_count = n;
  info.step_count = 1 << 30;
  info.dt_s = 1.0 / 60.0;
  fragsim::OcclusionMetric metric{fragsim::MetricsDef{}};
  metric.begin(info, snap);
  for (auto _ : state) {
    ++snap.step;
    metric.observe(snap);
  }
  fragsim::RunSummary summary;
  metric.fill(summary);
  state.counters["occlusion_mean"] = summary.occlusion.mean;
  state.counters["ns_per_fragment"] =
      benchmark::Counter(static_cast<double>(n) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_OcclusionObserve)->Arg(1728)->Unit(benchmark::kMicrosecond);

}  // namespace
