// The cost metric on durations fed by hand (never measured ones): nearest-rank quantiles of the
// physics and strategy times per step, in milliseconds. The tolerance 1e-12 ms covers the
// seconds-to-milliseconds product's rounding.

#include "metrics/cost_metric.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "metrics/run_summary.hpp"

namespace fragsim {
namespace {

constexpr double kTol_ms = 1e-12;

// A run whose step k (1-based) took physics_s[k - 1] and strategy_s[k - 1].
void feed(CostMetric& metric, const std::vector<double>& physics_s,
          const std::vector<double>& strategy_s) {
  const int steps = static_cast<int>(physics_s.size());
  StepSnapshot snap;
  metric.begin({nullptr, "test", 0, steps, 1.0 / 60.0}, snap);
  for (int k = 1; k <= steps; ++k) {
    snap.step = k;
    snap.physics_s = physics_s[static_cast<std::size_t>(k - 1)];
    snap.strategy_s = strategy_s[static_cast<std::size_t>(k - 1)];
    metric.observe(snap);
  }
}

TEST(CostMetric, QuantileIsTheNearestRank) {
  // Rank ceil(q n), counted from 1: of 5 values the median is the 3rd, the 95th percentile the 5th.
  const std::vector<double> five{5, 1, 4, 2, 3};
  EXPECT_EQ(CostMetric::quantile(five, 0.5), 3.0);
  EXPECT_EQ(CostMetric::quantile(five, 0.95), 5.0);
  EXPECT_EQ(CostMetric::quantile(five, 0.0), 1.0);  // rank 0 is clamped to the smallest
  EXPECT_EQ(CostMetric::quantile(five, 1.0), 5.0);
  // Of 1..20 the 95th percentile is the 19th value, and the median of an even count the lower.
  std::vector<double> twenty;
  for (int i = 20; i >= 1; --i) twenty.push_back(i);
  EXPECT_EQ(CostMetric::quantile(twenty, 0.95), 19.0);
  EXPECT_EQ(CostMetric::quantile(twenty, 0.5), 10.0);
  EXPECT_EQ(CostMetric::quantile({}, 0.5), 0.0);
}

TEST(CostMetric, FillsMediansAndP95InMillisecondsFromTheStepsTimes) {
  CostMetric metric;
  feed(metric, {0.004, 0.001, 0.003, 0.002}, {0.0, 0.0, 0.0, 0.010});
  EXPECT_EQ(metric.physics_s(), (std::vector<double>{0.004, 0.001, 0.003, 0.002}));
  RunSummary s;
  metric.fill(s);
  EXPECT_NEAR(s.cost.physics_ms_median, 2.0, kTol_ms);  // rank 2 of 1, 2, 3, 4 ms
  EXPECT_NEAR(s.cost.physics_ms_p95, 4.0, kTol_ms);     // rank ceil(3.8) = 4
  EXPECT_EQ(s.cost.strategy_ms_median, 0.0);
  EXPECT_NEAR(s.cost.strategy_ms_p95, 10.0, kTol_ms);
}

TEST(CostMetric, BeginStartsAFreshSample) {
  CostMetric metric;
  feed(metric, {0.5, 0.5, 0.5}, {0.5, 0.5, 0.5});
  feed(metric, {0.001}, {0.002});
  EXPECT_EQ(metric.physics_s(), (std::vector<double>{0.001}));
  EXPECT_EQ(metric.strategy_s(), (std::vector<double>{0.002}));
  RunSummary s;
  metric.fill(s);
  EXPECT_NEAR(s.cost.physics_ms_p95, 1.0, kTol_ms);
  EXPECT_NEAR(s.cost.strategy_ms_median, 2.0, kTol_ms);
}

}  // namespace
}  // namespace fragsim
