// A whole run (sim/simulation.cpp): the step count a scene's duration and step give, and
// simulate() driving a Run from the explosion to its last step, each step observed once. Numbers
// by hand: one box at 10 m/s without gravity or ground moves 10 dt per step.

#include "sim/simulation.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "sim/scene_strategies.hpp"
#include "support/test_scenes.hpp"

namespace fragsim {
namespace {

TEST(Simulation, StepCountIsTheDurationOverTheStepRoundedUp) {
  Scene s;
  s.sim.duration_s = 3.0;
  s.sim.dt_s = 1.0 / 60.0;
  EXPECT_EQ(s.step_count(), 180);  // 3 / (1/60) is 180 plus a rounding: not 181
  s.sim.duration_s = 1.0;
  EXPECT_EQ(s.step_count(), 60);
  s.sim.dt_s = 0.3;  // 3.33 steps: the last one ends past the duration
  EXPECT_EQ(s.step_count(), 4);
  s.sim.duration_s = 0.5;
  s.sim.dt_s = 0.25;
  EXPECT_EQ(s.step_count(), 2);
}

// The step and time of each snapshot, the last fragment position, and the calls.
class Recorder final : public RunObserver {
 public:
  int begins = 0;
  int ends = 0;
  std::vector<int> steps;
  std::vector<double> times_s;
  double last_z_m = 0.0;
  void begin(const RunInfo&, const StepSnapshot& s) override {
    ++begins;
    keep(s);
  }
  void observe(const StepSnapshot& s) override { keep(s); }
  void end() override { ++ends; }

 private:
  void keep(const StepSnapshot& s) {
    steps.push_back(s.step);
    times_s.push_back(s.t_s);
    last_z_m = s.fragments.front().position_m.z();
  }
};

TEST(Simulation, SimulateObservesTheExplosionAndEveryStepOnce) {
  Scene scene = test::single_fragment({0.0, 1.6, -10.0}, 10.0);
  scene.sim.duration_s = 0.5;  // 30 steps of 1/60 s
  const std::unique_ptr<SceneStrategy> none = make_strategy("none", scene);
  Recorder recorder;
  RunObserver* const observers[] = {&recorder};
  const RunTotals totals = simulate(scene, *none, observers);
  EXPECT_EQ(totals.steps, 30);
  EXPECT_EQ(recorder.begins, 1);
  EXPECT_EQ(recorder.ends, 1);
  ASSERT_EQ(recorder.steps.size(), 31u);
  for (int k = 0; k <= 30; ++k) {
    EXPECT_EQ(recorder.steps[static_cast<std::size_t>(k)], k);
    EXPECT_NEAR(recorder.times_s[static_cast<std::size_t>(k)], k / 60.0, 1e-12) << k;
  }
  // 10 m/s toward the camera for 0.5 s: from z = -10 to -5 (30 roundings of 1/6 m at most).
  EXPECT_NEAR(recorder.last_z_m, -5.0, 1e-9);
}

}  // namespace
}  // namespace fragsim
