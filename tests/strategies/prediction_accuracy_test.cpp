// The predictors against the simulation: a free fragment's simulated positions lie on the
// `discrete` predictor's parabola to rounding error, and `thesis` drifts by g t dt / 2.

#include <gtest/gtest.h>

#include <array>

#include "control/strategies/collision_prediction.hpp"
#include "sim/scene_strategies.hpp"
#include "sim/simulation.hpp"
#include "support/test_scenes.hpp"

namespace fragsim {
namespace {

// A fragment thrown up and forward under gravity, no ground, for 5 s.
Scene free_flight(double dt_s) {
  Scene s = test::single_fragment({0.0, 1.6, -10.0}, 10.0);
  s.explosion.offset_m = {0.0, -1.0, -1.0};  // radial push up and toward the camera
  s.explosion.spin_radps = 5.0;
  s.sim.gravity_mps2 = {0.0, -9.81, 0.0};
  s.sim.duration_s = 5.0;
  s.sim.dt_s = dt_s;
  return s;
}

class PredictionAccuracy : public ::testing::TestWithParam<double> {};

TEST_P(PredictionAccuracy, DiscreteLandsOnTheSimulatedPath) {
  const double dt = GetParam();
  const Scene scene = free_flight(dt);
  auto none = make_strategy("none", scene);
  test::Recorder rec;
  const std::array<RunObserver*, 1> obs{&rec};
  simulate(scene, *none, obs);
  const FragmentState& f0 = rec.steps.front().fragments[0];
  const BallisticPath discrete =
      predicted_path(f0, scene.sim.gravity_mps2, Predictor::kDiscrete, dt);
  const BallisticPath thesis = predicted_path(f0, scene.sim.gravity_mps2, Predictor::kThesis, dt);
  double worst_discrete_m = 0.0;
  for (std::size_t k = 0; k < rec.steps.size(); ++k) {
    const double t = static_cast<double>(k) * dt;
    const Eigen::Vector3d sim = rec.steps[k].fragments[0].position_m;
    worst_discrete_m = std::max(worst_discrete_m, (discrete.at(t) - sim).norm());
    // The thesis's (3.1) is off by exactly g t dt / 2 (to rounding).
    EXPECT_NEAR((thesis.at(t) - sim).norm(), 0.5 * 9.81 * t * dt, 1e-9) << "t = " << t;
  }
  // Positions reach ~120 m: 1e-9 m is about 1e4 ulps of accumulated rounding.
  EXPECT_LT(worst_discrete_m, 1e-9);
}

INSTANTIATE_TEST_SUITE_P(SeveralSteps, PredictionAccuracy,
                         ::testing::Values(1.0 / 30.0, 1.0 / 60.0, 1.0 / 240.0, 1.0 / 1000.0));

}  // namespace
}  // namespace fragsim
