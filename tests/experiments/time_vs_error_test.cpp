// The time-against-error bench on cases worked out by hand: free flight, where ODE's positions lie
// on the parabola with velocity V + g dt / 2, so two step sizes differ by |g| t (dt1 - dt2) / 2;
// a drop onto the ground, where the thesis predictor is off by |g| t dt / 2 at first contact.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <sstream>

#include "experiments/accuracy_probe.hpp"
#include "experiments/time_vs_error.hpp"
#include "io/number_format.hpp"
#include "sim/scene_strategies.hpp"
#include "sim/simulation.hpp"
#include "support/flight_scenes.hpp"
#include "support/test_scenes.hpp"

namespace fragsim {
namespace {

using test::away_flight;
using test::kG;

TEST(TimeVsError, FlightErrorBetweenStepSizesIsHalfGTimesTheirDifference) {
  const Scene base = away_flight();
  TimeVsErrorOptions o;
  o.strategy = "none";
  o.repeats = 1;
  const std::vector<BenchConfig> configs = {
      {"dt 1/60", "dt", {{"simulation.dt_s", format_double(1.0 / 60.0)}}},
      {"dt 1/120", "dt", {{"simulation.dt_s", format_double(1.0 / 120.0)}}},
      {"dt 1/480", "dt", {{"simulation.dt_s", format_double(1.0 / 480.0)}}},
  };
  std::vector<BenchDuplicate> dups;
  const std::vector<BenchRow> rows =
      run_time_vs_error(base, configs, reference_bench_config(), o, {}, &dups);
  // dt 1/480 with `auto` is the exact solver at 1/480: the reference itself, not run twice.
  ASSERT_EQ(dups.size(), 1u);
  EXPECT_EQ(dups[0].name, "dt 1/480");
  EXPECT_EQ(dups[0].same_as, "reference");
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows[0].config.name, "reference");
  EXPECT_EQ(rows[0].flight_error_mean_m, 0.0);
  EXPECT_EQ(rows[0].steps, 480);

  // Samples at t_j = j / 30, j = 1..30: the mean of t_j is 31 / 60 s, the largest 1 s.
  for (std::size_t r = 1; r < rows.size(); ++r) {
    const double ddt = rows[r].dt_s - 1.0 / 480.0;
    EXPECT_NEAR(rows[r].flight_error_mean_m, 0.5 * kG * ddt * 31.0 / 60.0, 1e-9)
        << rows[r].config.name;
    EXPECT_NEAR(rows[r].flight_error_max_m, 0.5 * kG * ddt * 1.0, 1e-9) << rows[r].config.name;
    // Never touching anything, every sample is flight.
    EXPECT_EQ(rows[r].position_error_mean_m, rows[r].flight_error_mean_m);
    EXPECT_EQ(rows[r].near_fragments, 0);
    EXPECT_EQ(rows[r].candidate_difference, 0);
  }
}

TEST(TimeVsError, ConfigurationErrorsNameTheConfiguration) {
  const Scene base = away_flight();
  TimeVsErrorOptions o;
  o.strategy = "none";
  o.repeats = 1;
  try {
    run_time_vs_error(base, {{"odd", "custom", {{"simulation.dt_s", "0.025"}}}},
                      reference_bench_config(), o);
    FAIL() << "a step that does not divide 1/30 s must be refused";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("bench config 'odd'"), std::string::npos) << e.what();
  }
  EXPECT_THROW(run_time_vs_error(base, {{"bad", "custom", {{"simulation.dt_s", "-1"}}}},
                                 reference_bench_config(), o),
               SceneError);
}

BenchRow row(const std::string& name, double time_s, double error_m) {
  BenchRow r;
  r.config.name = name;
  r.compute_s_per_sim_s = time_s;
  r.flight_error_mean_m = error_m;
  return r;
}

TEST(TimeVsError, ParetoFrontKeepsOnlyUndominatedRows) {
  std::vector<BenchRow> rows = {row("slow exact", 4.0, 0.0), row("fast rough", 1.0, 1.0),
                                row("dominated", 2.0, 1.5), row("middle", 2.0, 0.5),
                                row("tie on time, worse", 2.0, 0.6)};
  mark_pareto_front(rows);
  EXPECT_TRUE(rows[0].pareto);
  EXPECT_TRUE(rows[1].pareto);
  EXPECT_FALSE(rows[2].pareto);
  EXPECT_TRUE(rows[3].pareto);
  EXPECT_FALSE(rows[4].pareto);
}

// The bench names no strategy: after the shared groups it tries what each strategy declares of
// its own accuracy settings, so edge gets its predictor and replan rows and edge-min none.
TEST(TimeVsError, StrategyTuningComesFromItsDeclaration) {
  auto groups_of = [](const std::string& strategy) {
    std::vector<std::string> names;
    for (const BenchConfig& c : standard_bench_configs(strategy)) {
      if (c.group == "predictor" || c.group == "replan") names.push_back(c.name);
    }
    return names;
  };
  EXPECT_EQ(groups_of("edge"),
            (std::vector<std::string>{"predictor thesis", "predictor discrete", "replan never",
                                      "replan contact", "replan always"}));
  EXPECT_TRUE(groups_of("edge-min").empty());
  const std::vector<BenchConfig> edge = standard_bench_configs("edge");
  const auto discrete = std::find_if(edge.begin(), edge.end(), [](const BenchConfig& c) {
    return c.name == "predictor discrete";
  });
  ASSERT_NE(discrete, edge.end());
  ASSERT_EQ(discrete->overrides.size(), 1u);
  EXPECT_EQ(discrete->overrides[0].key, "edge.predictor");
  EXPECT_EQ(discrete->overrides[0].value, "discrete");
}

// The probe measures each strategy against the path it predicts with.
TEST(TimeVsError, ProbedPathIsTheStrategysOwn) {
  Scene scene = test::single_fragment({0.0, 1.6, -10.0});
  EXPECT_EQ(make_strategy("edge", scene)->path_predictor(), Predictor::kThesis);
  scene.strategies.edge.predictor = Predictor::kDiscrete;
  EXPECT_EQ(make_strategy("edge", scene)->path_predictor(), Predictor::kDiscrete);
  EXPECT_EQ(make_strategy("edge-min", scene)->path_predictor(), Predictor::kDiscrete);
  EXPECT_EQ(make_strategy("none", scene)->path_predictor(), Predictor::kDiscrete);
}

}  // namespace
}  // namespace fragsim
