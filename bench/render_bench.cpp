// One 640x360 frame of the default scene (1728 fragments) drawn by the software rasteriser, at the
// explosion (a compact cube far away), in flight and at the camera (large boxes, near-plane cuts).
// Run: build/release/bench/fragsim_bench --benchmark_filter=Render --benchmark_repetitions=5

#include <benchmark/benchmark.h>

#include "render/frame_renderer.hpp"
#include "sim/run.hpp"
#include "sim/scene_file.hpp"
#include "sim/scene_strategies.hpp"

namespace {

void BM_RenderFrame(benchmark::State& state) {
  const fragsim::Scene scene = fragsim::load_scene(FRAGSIM_DATA_DIR "/scenes/front.ini");
  const int step = static_cast<int>(state.range(0));
  auto none = fragsim::make_strategy("none", scene);
  fragsim::Run run(scene, *none);
  while (run.state().step < step) run.step();
  fragsim::FrameStyle style;
  style.overlays.cuts = true;
  fragsim::FrameRenderer renderer(scene, style);
  for (auto _ : state) {
    const fragsim::Image image = renderer.render(run.state());
    benchmark::DoNotOptimize(image.bytes().data());
  }
}
BENCHMARK(BM_RenderFrame)->Arg(0)->Arg(24)->Arg(45)->Unit(benchmark::kMillisecond);

}  // namespace
