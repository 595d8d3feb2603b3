// The exact stepper's fallback (World::step): ODE's Dantzig solver can fail an island's LCP
// ("LCP internal error, s <= 0") and then leaves the forces of the rows it had not solved at zero.
// World redoes such a step with QuickStep from the state before it, so the run stays free of ODE
// messages, and counts the retry.

#include <gtest/gtest.h>

#include <memory>

#include "sim/scene_file.hpp"
#include "sim/scene_strategies.hpp"
#include "sim/simulation.hpp"
#include "sim/world.hpp"

namespace fragsim {
namespace {

// The soak's seed 5085: 27 cubes thrown from the eye with gravity off, at dt 1e-3 s, `edge` pushing
// them at up to 8.9e3 m/s^2 onto the ground. Before the fallback the exact solver printed the
// message 198 times in this run (after the first failure, zeroed contact forces let the cubes
// sink and the next steps failed too).
constexpr const char* kSeed5085 =
    "[simulation]\ndt_s = 0.001\nduration_s = 0.3\nseed = 5085\ngravity_mps2 = 0 0 0\n"
    "[object]\ncentre_m = 0 1.6 -0.05\nsize_m = 0.2698829507656053\nsplits = 3\n"
    "[explosion]\nspeed_mps = 1.2467003175675704\njitter = 0.8940971774161\n"
    "spin_radps = 10.01826573004127\ntoward_camera_mps = 7.206270684519145\n"
    "[camera]\nwaypoints_m = 0 1.6 0\nlook_at_m = 0 1.6 -10\nspeed_mps = 0\n"
    "max_speed_mps = 67.39494886141362\nfovy_deg = 65.40770830306015\n"
    "[edge]\nk = 163.53809150595615\na_max_mps2 = 8855.451055329871\npredictor = discrete\n"
    "reach = growing\nreplan = always\n";

TEST(WorldExactStep, FailedLcpStepIsRedoneWithoutAMessage) {
  const Scene scene = parse_scene(kSeed5085, "seed5085.ini");
  ASSERT_TRUE(scene.sim.uses_exact_solver());
  auto edge = make_strategy("edge", scene);
  const long retries_before = World::exact_step_retries();
  const RunTotals totals = simulate(scene, *edge);
  EXPECT_EQ(totals.ode_messages, 0);
  EXPECT_EQ(totals.steps, 300);
  EXPECT_GE(World::exact_step_retries() - retries_before, 1);
}

// A scene whose exact steps never fail is stepped by the exact solver alone: no retry.
TEST(WorldExactStep, NoRetryWhereTheLcpHolds) {
  const Scene scene = parse_scene(
      "[simulation]\nduration_s = 1\nseed = 3\n[object]\nsplits = 3\n[ground]\nenabled = on\n",
      "cubes.ini");
  auto none = make_strategy("none", scene);
  const long retries_before = World::exact_step_retries();
  const RunTotals totals = simulate(scene, *none);
  EXPECT_EQ(totals.ode_messages, 0);
  EXPECT_EQ(World::exact_step_retries() - retries_before, 0);
}

}  // namespace
}  // namespace fragsim
