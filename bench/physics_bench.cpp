// One physics step (World::set_camera + World::step: collision detection and the ODE step) at
// 1728 fragments, per configuration, in the state that matters: the default scene's cube with the
// blast not aimed (explosion.toward_camera_mps = 0), so by t = 1 s nearly every fragment is on
// the ground. Each repetition builds the world, steps it to t = 1 s untimed, then times the 60
// steps from t = 1 s to 2 s (a fixed window, so every repetition measures the same steps).
// Also the whole default scene (180 steps, aimed blast) with and without the skips.
// And convex pieces against boxes (BM_PhysicsShapes): 1,000 of each, in flight and on the ground.
// Run: build/release/bench/fragsim_bench --benchmark_filter=Physics --benchmark_repetitions=5
// --benchmark_report_aggregates_only=true

#include <benchmark/benchmark.h>

#include <algorithm>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "debris/debris_def.hpp"
#include "sim/camera_path.hpp"
#include "sim/explosion.hpp"
#include "sim/scene_file.hpp"
#include "sim/world.hpp"
#include "support/convex_shapes.hpp"

namespace {

using Overrides = std::vector<fragsim::SceneOverride>;

constexpr int kSettleSteps = 60;  // t = 0 is all in flight; by 1 s the cube lies on the ground
constexpr int kTimedSteps = 60;

fragsim::Scene landed_scene(Overrides overrides) {
  overrides.push_back({"explosion.toward_camera_mps", "0"});
  return fragsim::load_scene(FRAGSIM_DATA_DIR "/scenes/front.ini", overrides);
}

// Step k of a run: the camera moved to its pose at k dt, then one physics step.
void step_with_camera(fragsim::World& world, const fragsim::CameraPath& path, double dt_s, int k) {
  const double t_s = k * dt_s;
  world.set_camera(path.pose_at(t_s), path.velocity_at(t_s));
  world.step(dt_s);
}

void BM_PhysicsStep(benchmark::State& state, Overrides overrides) {
  const fragsim::Scene scene = landed_scene(std::move(overrides));
  const fragsim::CameraPath path(scene.camera);
  fragsim::World world(scene, {}, fragsim::explode(scene));
  int k = 0;
  auto advance = [&] { step_with_camera(world, path, scene.sim.dt_s, k++); };
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

// 1,000 convex pieces against 1,000 boxes of the default scene's size (0.1 m cubes, 600 kg/m^3):
// random hulls of 8 to 20 points in a ball of the cube's volume (radius 0.062 m), each its own
// shape, against the 0.1 m boxes, from a 10 x 10 x 10 grid 0.3 m apart, 1.5 to 4.2 m up, thrown
// at up to 2 m/s with up to 10 rad/s of spin (seeded: the same pieces and throws every run).
// `flight`: no ground, 60 steps from t = 0. `ground`: 180 steps untimed (3 s: every fragment has
// landed and, with the exact stepper, come to rest), then 60 timed. `ground_collisions`: the same
// with fragment collisions on (QuickStep, 20 iterations): the grid falls in columns that touch.
// `voronoi`: the cells of a 1 m cube cut into 1,000 by the debris module (object.pattern =
// voronoi: 1 litre on average, as the boxes, but from a few tenths to a few litres), each placed
// where the grid puts a fragment and thrown the same way.
enum class Piece { kBox, kConvex, kVoronoi };
enum class Phase { kFlight, kGround, kGroundCollisions };

constexpr int kShapesCount = 1000;

const std::vector<fragsim::Piece>& voronoi_cells() {
  static const std::vector<fragsim::Piece> cells = [] {
    fragsim::DebrisDef def;
    def.pattern = fragsim::DebrisPattern::kVoronoi;
    def.size_m = 1.0;
    def.pieces = kShapesCount;
    def.density_kgpm3 = 600.0;
    return fragsim::make_pieces(def);
  }();
  return cells;
}

std::vector<fragsim::FragmentSpawn> shapes_spawns(Piece piece) {
  std::mt19937_64 rng(14);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_int_distribution<int> points(8, 20);
  constexpr double kDensity_kgpm3 = 600.0;
  constexpr double kHalf_m = 0.05;
  std::vector<fragsim::FragmentSpawn> spawns;
  for (int i = 0; i < kShapesCount; ++i) {
    fragsim::FragmentSpawn s;
    s.position_m = {0.3 * (i % 10) - 1.35, 1.5 + 0.3 * ((i / 10) % 10), -5.0 - 0.3 * (i / 100)};
    s.velocity_mps = 2.0 * Eigen::Vector3d(u(rng), u(rng), u(rng));
    s.angular_velocity_radps = 10.0 * Eigen::Vector3d(u(rng), u(rng), u(rng));
    // Drawn for both kinds, so both throw every fragment the same way.
    fragsim::ConvexShape hull = fragsim::test::random_hull(rng, points(rng), 0.062);
    if (piece == Piece::kVoronoi) {
      const fragsim::Piece& cell = voronoi_cells()[static_cast<std::size_t>(i)];
      s.half_extents_m = cell.shape->half_extents_m;
      s.mass_kg = cell.mass_kg;
      s.shape = cell.shape;
    } else if (piece == Piece::kConvex) {
      s.half_extents_m = hull.half_extents_m;
      s.mass_kg = kDensity_kgpm3 * hull.volume_m3;
      s.shape = std::make_shared<const fragsim::ConvexShape>(std::move(hull));
    } else {
      s.half_extents_m = Eigen::Vector3d::Constant(kHalf_m);
      s.mass_kg = kDensity_kgpm3 * 8.0 * kHalf_m * kHalf_m * kHalf_m;
    }
    spawns.push_back(std::move(s));
  }
  return spawns;
}

// `contacts`: simulation.convex_ground_contacts (8 keeps every corner ODE returns, as the rows
// published before the scene default became 4 did; the `_4_contacts` rows are the default).
void BM_PhysicsShapes(benchmark::State& state, Piece piece, Phase phase, int contacts = 8) {
  Overrides overrides;
  overrides.push_back({"simulation.convex_ground_contacts", std::to_string(contacts)});
  if (phase == Phase::kFlight) overrides.push_back({"ground.enabled", "off"});
  if (phase == Phase::kGroundCollisions) {
    overrides.push_back({"simulation.fragment_collisions", "on"});
  }
  const fragsim::Scene scene = fragsim::load_scene(FRAGSIM_DATA_DIR "/scenes/front.ini", overrides);
  const fragsim::CameraPath path(scene.camera);
  fragsim::World world(scene, {}, shapes_spawns(piece));
  int k = 0;
  auto advance = [&] { step_with_camera(world, path, scene.sim.dt_s, k++); };
  if (phase != Phase::kFlight) {
    for (int i = 0; i < 3 * kSettleSteps; ++i) advance();
  }
  for (auto _ : state) advance();
  state.counters["awake_at_end"] = world.awake_count();
  if (phase == Phase::kFlight) return;
  // A piece that passed through the ground costs no contacts: the count keeps the times honest
  // (before src/sim/ground_sweep.cpp, with 4 ground contacts a piece, 269 of the random hulls and
  // 46 of the cells were wholly below it by the end).
  std::vector<fragsim::FragmentState> states = world.init_states();
  world.read(states);
  const double ground_y_m = scene.ground.height_m;
  state.counters["below_ground_at_end"] = static_cast<double>(std::count_if(
      states.begin(), states.end(),
      [&](const fragsim::FragmentState& f) { return f.position_m.y() + f.radius_m < ground_y_m; }));
}

#define PHYSICS_SHAPES(name, ...)                        \
  BENCHMARK_CAPTURE(BM_PhysicsShapes, name, __VA_ARGS__) \
      ->Iterations(kTimedSteps)                          \
      ->Unit(benchmark::kMillisecond)

PHYSICS_SHAPES(boxes_flight, Piece::kBox, Phase::kFlight);
PHYSICS_SHAPES(convex_flight, Piece::kConvex, Phase::kFlight);
PHYSICS_SHAPES(boxes_ground, Piece::kBox, Phase::kGround);
PHYSICS_SHAPES(convex_ground, Piece::kConvex, Phase::kGround);
PHYSICS_SHAPES(boxes_ground_collisions, Piece::kBox, Phase::kGroundCollisions);
PHYSICS_SHAPES(voronoi_flight, Piece::kVoronoi, Phase::kFlight);
PHYSICS_SHAPES(voronoi_ground, Piece::kVoronoi, Phase::kGround);
PHYSICS_SHAPES(voronoi_ground_collisions, Piece::kVoronoi, Phase::kGroundCollisions);
PHYSICS_SHAPES(convex_ground_collisions, Piece::kConvex, Phase::kGroundCollisions);
PHYSICS_SHAPES(voronoi_ground_4_contacts, Piece::kVoronoi, Phase::kGround, 4);
PHYSICS_SHAPES(voronoi_ground_collisions_4_contacts, Piece::kVoronoi, Phase::kGroundCollisions, 4);

}  // namespace
