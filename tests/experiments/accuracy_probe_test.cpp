// The accuracy probe on one box worked out by hand (support/flight_scenes.hpp): positions sampled
// every 1/30 s, and the thesis predictor off by |g| t dt / 2 at a dropped box's first contact.

#include "experiments/accuracy_probe.hpp"

#include <gtest/gtest.h>

#include <array>
#include <stdexcept>

#include "sim/scene_strategies.hpp"
#include "sim/simulation.hpp"
#include "support/flight_scenes.hpp"
#include "support/test_scenes.hpp"

namespace fragsim {
namespace {

using test::away_flight;
using test::drop;
using test::kG;

AccuracyProbe probe_run(const Scene& scene, Predictor predictor) {
  AccuracyProbe probe(1.0 / 30.0, predictor);
  auto none = make_strategy("none", scene);
  const std::array<RunObserver*, 1> obs{&probe};
  simulate(scene, *none, obs);
  return probe;
}

TEST(AccuracyProbe, SamplesEveryThirtiethOfASecond) {
  Scene s = away_flight();  // 1 s at dt 1/60: 60 steps, a sample every 2
  test::Recorder rec;
  AccuracyProbe probe(1.0 / 30.0, Predictor::kThesis);
  auto none = make_strategy("none", s);
  const std::array<RunObserver*, 2> obs{&rec, &probe};
  simulate(s, *none, obs);
  ASSERT_EQ(probe.samples().size(), 30u);
  for (std::size_t j = 0; j < 30; ++j) {
    EXPECT_EQ(probe.samples()[j][0], rec.steps[2 * (j + 1)].fragments[0].position_m) << j;
  }
  EXPECT_EQ(probe.predicted_contacts(), 0);  // it never touches anything
}

TEST(AccuracyProbe, RejectsASampleIntervalThatIsNotWholeSteps) {
  Scene s = away_flight();
  s.sim.dt_s = 0.025;  // 1/30 s is 1.33 steps
  EXPECT_THROW(probe_run(s, Predictor::kThesis), std::invalid_argument);
}

TEST(AccuracyProbe, ThesisPredictorIsOffByHalfGTDtAtFirstContact) {
  const Scene s = drop();
  const double dt = s.sim.dt_s;
  const AccuracyProbe thesis = probe_run(s, Predictor::kThesis);
  ASSERT_EQ(thesis.predicted_contacts(), 1);
  // Bottom face at 1.95 m falls to the ground in sqrt(2 * 1.95 / g) = 0.63 s.
  const double t_contact_s = thesis.first_contact_s()[0];
  EXPECT_GT(t_contact_s, 0.60);
  EXPECT_LT(t_contact_s, 0.70);
  // Checked one step before the contact's step: tau = t_contact - dt.
  const double tau_s = t_contact_s - dt;
  EXPECT_NEAR(thesis.prediction_error_mean_m(), 0.5 * kG * tau_s * dt, 1e-12);
  EXPECT_NEAR(thesis.prediction_error_max_m(), 0.5 * kG * tau_s * dt, 1e-12);

  const AccuracyProbe discrete = probe_run(s, Predictor::kDiscrete);
  EXPECT_LT(discrete.prediction_error_max_m(), 1e-12);
}

}  // namespace
}  // namespace fragsim
