// One physics step (World::set_camera + World::step: collision detection and the ODE step) at
// 1728 fragments, per configuration, in the state that matters: the default scene's cube with the
// blast not aimed (explosion.toward_camera_mps = 0), so by t = 1 s nearly every fragment is on
// the ground. Each repetition builds the world, steps it to t = 1 s untimed, then times the 60
// steps from t = 1 s to 2 s (a fixed window, so every repetition measures the same steps).
// Also the whole default scene (180 steps, aimed blast) with and without the skips.
// Run: build/release/bench/fragsim_bench --benchmark_filter=Physics --benchmark_repetitions=5
// --benchmark_report_aggregates_only=true

#include <benchmark/benchmark.h>

#include <string>
#include <vector>

#include "sim/camera_path.hpp"
#include "sim/explosion.hpp"
#include "sim/scene_file.hpp"
#include "sim/world.hpp"

namespace {

using Overrides = std::vector<fragsim::SceneOverride>;

constexpr int kSettleSteps = 60;  // t = 0 is all in flight; by 1 s the cube lies on the ground
constexpr int kTimedSteps = 60;

fragsim::Scene landed_scene(Overrides overrides) {
  overrides.push_back({"explosion.toward_camera_mps", "0"});
  return fragsim::load_scene(FRAGSIM_DATA_DIR "/scenes/front.ini", overrides);
}

void BM_PhysicsStep(benchmark::State& state, Overrides overrides) {
  const fragsim::Scene scene = landed_scene(std::move(overrides));
  const fragsim::CameraPath path(scene.camera);
  fragsim::World world(scene, {}, fragsim::explode(scene));
  const double dt = scene.sim.dt_s;
  int k = 0;
  auto advance = [&] {
    const double t = k * dt;
    world.set_camera(path.pose_at(t), path.velocity_at(t));
    world.step(dt);
    ++k;
  };
  for (int i = 0; i < kSettleSteps; ++i) advance();
  for (auto _ : state) advance();
  state.counters["awake_at_end"] = world.awake_count();
}

#define PHYSICS_STEP(name, ...)                                   \
  BENCHMARK_CAPTURE(BM_PhysicsStep, name, Overrides{__VA_ARGS__}) \
      ->Iterations(kTimedSteps)                                   \
      ->Unit(benchmark::kMillisecond)

PHYSICS_STEP(ballistic, {"ground.enabled", "off"});
PHYSICS_STEP(ground_exact, {"simulation.solver", "exact"});
PHYSICS_STEP(ground_quick5, {"simulation.solver", "quick"}, {"simulation.solver_iterations", "5"});
PHYSICS_STEP(ground_quick10, {"simulation.solver", "quick"},
             {"simulation.solver_iterations", "10"});
PHYSICS_STEP(ground_quick20, {"simulation.solver", "quick"},
             {"simulation.solver_iterations", "20"});
PHYSICS_STEP(ground_quick40, {"simulation.solver", "quick"},
             {"simulation.solver_iterations", "40"});
PHYSICS_STEP(ground_exact_auto_disable, {"simulation.solver", "exact"},
             {"simulation.auto_disable", "on"});
PHYSICS_STEP(ground_quick20_auto_disable, {"simulation.solver", "quick"},
             {"simulation.auto_disable", "on"});
PHYSICS_STEP(collisions_quick20, {"simulation.fragment_collisions", "on"});
PHYSICS_STEP(collisions_quick20_auto_disable, {"simulation.fragment_collisions", "on"},
             {"simulation.auto_disable", "on"});

// The default scene as it is (aimed blast, 180 steps), physics only, without and with the skips:
// most fragments fly past the camera and land behind it, out of view, from t ~ 0.8 s on. The
// time is per run of 180 steps, building the world excluded.
void BM_PhysicsDefaultScene(benchmark::State& state, Overrides overrides) {
  const fragsim::Scene scene = fragsim::load_scene(FRAGSIM_DATA_DIR "/scenes/front.ini", overrides);
  const fragsim::CameraPath path(scene.camera);
  const std::vector<fragsim::FragmentSpawn> spawns = fragsim::explode(scene);
  const double dt = scene.sim.dt_s;
  int awake = 0;
  for (auto _ : state) {
    state.PauseTiming();
    fragsim::World world(scene, {}, spawns);
    state.ResumeTiming();
    for (int k = 0; k < scene.step_count(); ++k) {
      const double t = k * dt;
      world.set_camera(path.pose_at(t), path.velocity_at(t));
      world.step(dt);
    }
    awake = world.awake_count();
  }
  state.counters["awake_at_end"] = awake;
}
BENCHMARK_CAPTURE(BM_PhysicsDefaultScene, plain, Overrides{})->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PhysicsDefaultScene, auto_disable,
                  Overrides{{"simulation.auto_disable", "on"}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PhysicsDefaultScene, cull_resting,
                  Overrides{{"simulation.cull_resting", "on"}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_PhysicsDefaultScene, both,
                  Overrides{{"simulation.auto_disable", "on"}, {"simulation.cull_resting", "on"}})
    ->Unit(benchmark::kMillisecond);

}  // namespace
