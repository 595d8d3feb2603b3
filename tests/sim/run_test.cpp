// A run stepped by hand: the same run as simulate(), its state readable between steps, and the
// physics of a free fragment read at each of them.

#include "sim/run.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "sim/scene_file.hpp"
#include "sim/scene_strategies.hpp"
#include "sim/simulation.hpp"
#include "support/test_scenes.hpp"

namespace fragsim {
namespace {

constexpr double kDt = 1.0 / 60.0;

// front.ini made small: 64 fragments, half a second (30 steps at 60 Hz).
Scene small_front() {
  Scene s = load_scene(std::string(FRAGSIM_DATA_DIR) + "/scenes/front.ini");
  s.object.splits = 4;
  s.sim.duration_s = 0.5;
  return s;
}

// Every call an observer gets, in order, and the last fragments it saw.
class CallLog final : public RunObserver {
 public:
  int begins = 0;
  int ends = 0;
  int step_count = 0;      // as RunInfo gave it
  std::vector<int> steps;  // each snapshot's step, begin's included
  std::vector<double> times_s;
  std::vector<FragmentState> last;

  void begin(const RunInfo& info, const StepSnapshot& s) override {
    ++begins;
    step_count = info.step_count;
    keep(s);
  }
  void observe(const StepSnapshot& s) override { keep(s); }
  void end() override { ++ends; }

 private:
  void keep(const StepSnapshot& s) {
    steps.push_back(s.step);
    times_s.push_back(s.t_s);
    last.assign(s.fragments.begin(), s.fragments.end());
  }
};

// A strategy that keeps what each step told it, and pushes nothing.
class Listener final : public SceneStrategy {
 public:
  std::vector<StepContext> seen;
  std::vector<Eigen::Vector3d> first_fragment_m;
  std::string name() const override { return "listener"; }
  void reset(int) override { seen.clear(); }
  void step(const StepContext& ctx, SceneStepOutput&) override {
    seen.push_back(ctx);
    first_fragment_m.push_back(ctx.fragments[0].position_m);
  }
};

TEST(Run, SteppedToItsEndIsSimulate) {
  const Scene scene = small_front();
  auto by_hand = make_strategy("edge-min", scene);
  auto whole = make_strategy("edge-min", scene);
  CallLog hand_log;
  CallLog whole_log;
  RunObserver* hand_obs[] = {&hand_log};
  RunObserver* whole_obs[] = {&whole_log};

  fragsim::Run run(scene, *by_hand, hand_obs);
  EXPECT_EQ(hand_log.begins, 1);
  int steps = 0;
  while (!run.done()) {
    run.step();
    ++steps;
    EXPECT_EQ(hand_log.ends, 0) << "ended before finish()";
  }
  const RunTotals hand = run.finish();
  const RunTotals all = simulate(scene, *whole, whole_obs);

  EXPECT_EQ(steps, 30);
  EXPECT_EQ(hand.steps, 30);
  EXPECT_EQ(all.steps, 30);
  EXPECT_EQ(hand.nonfinite_fragments, all.nonfinite_fragments);
  EXPECT_EQ(hand.ode_messages, all.ode_messages);
  for (const CallLog* log : {&hand_log, &whole_log}) {
    EXPECT_EQ(log->begins, 1);
    EXPECT_EQ(log->ends, 1);
    EXPECT_EQ(log->step_count, 30);
    ASSERT_EQ(log->steps.size(), 31u);
    for (int k = 0; k <= 30; ++k) EXPECT_EQ(log->steps[k], k);
  }
  EXPECT_EQ(hand_log.times_s, whole_log.times_s);
  // The same run: every fragment where simulate() left it, bit for bit.
  ASSERT_EQ(hand_log.last.size(), whole_log.last.size());
  ASSERT_EQ(hand_log.last.size(), 64u);
  for (std::size_t i = 0; i < hand_log.last.size(); ++i) {
    EXPECT_EQ(hand_log.last[i].position_m, whole_log.last[i].position_m) << i;
    EXPECT_EQ(hand_log.last[i].velocity_mps, whole_log.last[i].velocity_mps) << i;
  }
}

TEST(Run, StateAdvancesByDtAndDoneAfterTheStepCount) {
  const Scene scene = small_front();
  ASSERT_EQ(scene.sim.dt_s, kDt);
  Listener listener;
  fragsim::Run run(scene, listener);
  EXPECT_EQ(run.step_count(), 30);
  for (int k = 0; k < 30; ++k) {
    ASSERT_FALSE(run.done()) << k;
    EXPECT_EQ(run.state().step, k);
    EXPECT_EQ(run.state().t_s, k * kDt);
    EXPECT_EQ(run.totals().steps, k);
    // What the strategy will be told is readable before it is told.
    const StepContext next = run.next_context();
    EXPECT_EQ(next.step, k);
    EXPECT_EQ(next.t_s, k * kDt);
    const Eigen::Vector3d first_m = run.state().fragments[0].position_m;
    run.step();
    ASSERT_EQ(listener.seen.size(), static_cast<std::size_t>(k + 1));
    const StepContext& told = listener.seen.back();
    EXPECT_EQ(told.step, next.step);
    EXPECT_EQ(told.t_s, next.t_s);
    EXPECT_EQ(told.camera.eye_m, next.camera.eye_m);
    EXPECT_EQ(told.camera_velocity_mps, next.camera_velocity_mps);
    EXPECT_EQ(listener.first_fragment_m.back(), first_m);
  }
  EXPECT_TRUE(run.done());
  EXPECT_EQ(run.state().step, 30);
  EXPECT_THROW(run.step(), std::logic_error);
  const RunTotals first = run.finish();
  const RunTotals again = run.finish();
  EXPECT_EQ(first.steps, 30);
  EXPECT_EQ(again.wall_s, first.wall_s);
}

// One fragment thrown up and away under gravity, nothing to hit: ODE's semi-implicit Euler adds
// g dt to the velocity, then moves by the new velocity, so after k steps (t = k dt)
//   v = v0 + g t,  x = x0 + v0 t + g dt^2 k (k + 1) / 2 = x0 + (v0 + g dt / 2) t + g t^2 / 2.
TEST(Run, AFreeFragmentReadBetweenStepsLiesOnItsParabola) {
  Scene scene = test::single_fragment({0.0, 1.6, -10.0}, 6.0);
  scene.explosion.offset_m = {0.0, -1.0, 1.0};  // radial push up and away from the camera
  scene.sim.gravity_mps2 = {0.0, -9.81, 0.0};
  scene.sim.duration_s = 1.0;
  auto none = make_strategy("none", scene);
  fragsim::Run run(scene, *none);
  ASSERT_EQ(run.state().fragments.size(), 1u);
  const Eigen::Vector3d x0 = run.state().fragments[0].position_m;
  const Eigen::Vector3d v0 = run.state().fragments[0].velocity_mps;
  // Up and away, 6 m/s along (0, 1, -1) / sqrt(2).
  EXPECT_NEAR(v0.y(), 6.0 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(v0.z(), -6.0 / std::sqrt(2.0), 1e-12);
  const Eigen::Vector3d g = scene.sim.gravity_mps2;
  while (!run.done()) {
    run.step();
    const int k = run.state().step;
    const double t = k * kDt;
    const FragmentState& f = run.state().fragments[0];
    const Eigen::Vector3d x = x0 + (v0 + 0.5 * kDt * g) * t + 0.5 * g * t * t;
    EXPECT_LT((f.position_m - x).norm(), 1e-11) << "step " << k;
    EXPECT_LT((f.velocity_mps - (v0 + g * t)).norm(), 1e-11) << "step " << k;
  }
  // The parabola's top at t = v0y / g ~ 0.43 s was passed: the fragment is falling.
  EXPECT_LT(run.state().fragments[0].velocity_mps.y(), -5.0);
}

}  // namespace
}  // namespace fragsim
