// Light pieces (World's mass unit, world.cpp): ODE's exact solver aborted the process
// (dxLDLTRemove: "d[i] != 0", or dxNormalize4) on pieces of about 1e-8 kg touching the ground, at
// any CFM. The world now steps them in a mass unit that keeps every piece's 1/m + r^2/I below
// 1e6 per kg, and refuses, with one line, pieces whose mass or inertia ODE cannot hold at all.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include <unistd.h>

#include "debris/mesh_file.hpp"
#include "io/input_error.hpp"
#include "sim/explosion.hpp"
#include "sim/scene_file.hpp"
#include "sim/scene_strategies.hpp"
#include "sim/simulation.hpp"
#include "sim/world.hpp"
#include "sim/world_probe.hpp"

namespace fragsim {
namespace {

// What a run's fragments did: how many touched something (the ground, here) at some step, and
// whether every state stayed finite.
class ContactWatch : public RunObserver {
 public:
  void begin(const RunInfo&, const StepSnapshot& initial) override { observe(initial); }
  void observe(const StepSnapshot& snap) override {
    for (const FragmentState& f : snap.fragments) {
      finite = finite && f.position_m.allFinite() && f.velocity_mps.allFinite();
      touches += f.touched ? 1 : 0;
      fastest_mps = std::max(fastest_mps, f.velocity_mps.norm());
    }
  }
  bool finite = true;
  long touches = 0;
  double fastest_mps = 0.0;
};

// The object just above the ground so its pieces land within the run, the exact solver forced.
std::string landing(const std::string& object_keys) {
  return "[simulation]\nduration_s = 0.5\nsolver = exact\n[object]\n" + object_keys +
         "[camera]\nwaypoints_m = 0 1.6 0\n";
}

void expect_lands_cleanly(const Scene& scene, double speed_bound_mps) {
  auto none = make_strategy("none", scene);
  ContactWatch watch;
  RunObserver* const observers[] = {&watch};
  const RunTotals totals = simulate(scene, *none, observers);
  EXPECT_EQ(totals.steps, 30);
  EXPECT_EQ(totals.nonfinite_fragments, 0);
  EXPECT_EQ(totals.ode_messages, 0);
  EXPECT_TRUE(watch.finite);
  EXPECT_GT(watch.touches, 0) << "no piece reached the ground: the case is not tested";
  // Nothing faster than the blast can throw it (5 m/s, jitter 0.3: 8 m/s) plus 0.5 s of fall.

  EXPECT_LT(watch.fastest_mps, speed_bound_mps);
}

// The inputs: 1,728 cubes of 0.41 mm (4.1e-8 kg), and 64 of 0.245 mm (8.8e-9 kg).
TEST(WorldLightPieces, TinyGridCubesLandUnderTheExactSolver) {
  expect_lands_cleanly(
      parse_scene(landing("centre_m = 0 0.0026 -8\nsize_m = 0.005\nsplits = 12\n"), "tiny.ini"),
      14.0);
  expect_lands_cleanly(
      parse_scene(landing("centre_m = 0 0.0006 -8\nsize_m = 0.001\nsplits = 4\n"), "tiny.ini"),
      14.0);
}

// Light by density instead of size: the thesis's 0.1 m cubes at 1e-6 kg/m^3 weigh 8e-10 kg.
TEST(WorldLightPieces, FeatherweightCubesLandUnderTheExactSolver) {
  expect_lands_cleanly(
      parse_scene(landing("centre_m = 0 0.61 -8\nsplits = 4\ndensity_kgpm3 = 1e-6\n"),
                  "feather.ini"),
      14.0);
}

// The same 0.41 mm pieces read back from a mesh file (convex hulls, not boxes).
TEST(WorldLightPieces, TinyMeshPiecesLandUnderTheExactSolver) {
  const Scene grid = parse_scene(landing("size_m = 0.005\nsplits = 12\n"), "tiny.ini");
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("fragsim_light_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string obj = (dir / "tiny.obj").string();
  write_pieces(scene_pieces(grid), obj);
  const Scene mesh =
      parse_scene(landing("centre_m = 0 0.0026 -8\nmesh_file = " + obj + "\n"), "tiny_mesh.ini");
  std::filesystem::remove_all(dir);
  ASSERT_TRUE(mesh.object.mesh_pieces);
  expect_lands_cleanly(mesh, 14.0);
}

// The mass unit is reported back in kg: a piece's mass and inertia read from the world are its
// own, whatever unit ODE holds them in.
TEST(WorldLightPieces, ProbeReadsMassInKilograms) {
  const Scene scene = parse_scene(landing("size_m = 0.001\nsplits = 4\n"), "tiny.ini");
  const std::vector<FragmentSpawn> spawns = explode(scene);
  const World world(scene, WorldNeeds{}, spawns);
  const ProbeMass m = WorldProbe::mass(world, 0);
  EXPECT_NEAR(m.mass_kg / spawns[0].mass_kg, 1.0, 1e-12);
  const double edge_m = 2.0 * spawns[0].half_extents_m.x();
  EXPECT_NEAR(m.inertia_kgm2(0, 0) / (spawns[0].mass_kg * edge_m * edge_m / 6.0), 1.0, 1e-12);
}

// Below what a double holds for ODE (a piece of 1e-300 m weighs nothing): one line naming the
// piece and the keys to change, before ODE is touched.
TEST(WorldLightPieces, MasslessPieceIsRefusedWithOneLine) {
  const Scene scene = parse_scene(landing("size_m = 1e-300\nsplits = 2\n"), "grain.ini");
  const std::vector<FragmentSpawn> spawns = explode(scene);
  try {
    const World world(scene, WorldNeeds{}, spawns);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find('\n'), std::string::npos);
    EXPECT_NE(what.find("piece 1 weighs 0 kg"), std::string::npos) << what;
    EXPECT_NE(what.find("object.size_m"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace fragsim
