// DeviationMetric on hand-built snapshots (support/hand_runs.hpp): no physics, every case worked
// out by hand. Distances of shifted positions carry rounding, hence the 1e-12 m tolerance; a run
// against itself must give exactly zero.

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "metrics/deviation_metric.hpp"
#include "metrics/run_summary.hpp"
#include "metrics/trajectory_record.hpp"
#include "support/hand_runs.hpp"

namespace fragsim {
namespace {

using test::make_run;
using test::play;
using test::record;
using test::Trajectory;

constexpr double kTol_m = 1e-12;

RunSummary deviation(const TrajectoryRecord& ref, const Trajectory& run, double threshold_m,
                     std::vector<double>* largest_m = nullptr) {
  DeviationMetric metric(ref, threshold_m);
  play(run, metric);
  RunSummary s;
  metric.fill(s);
  if (largest_m) *largest_m = metric.largest_deviation_m();
  return s;
}

TEST(DeviationMetric, RunAgainstItselfIsExactlyZero) {
  const Trajectory run = make_run(5, 10);
  const TrajectoryRecord ref = record(run);
  std::vector<double> largest_m;
  const RunSummary s = deviation(ref, run, 0.01, &largest_m);
  EXPECT_EQ(s.deviation.mean_m, 0.0);
  EXPECT_EQ(s.deviation.max_m, 0.0);
  EXPECT_EQ(s.deviation.deviated_share, 0.0);
  ASSERT_EQ(largest_m.size(), 5u);
  for (double d : largest_m) EXPECT_EQ(d, 0.0);
}

TEST(DeviationMetric, OneFragmentShiftedAtOneStep) {
  const Trajectory ref_run = make_run(4, 6);
  const TrajectoryRecord ref = record(ref_run);
  Trajectory run = ref_run;
  run[3][2].position_m += Eigen::Vector3d(0.0, 0.02, 0.0);
  std::vector<double> largest_m;
  const RunSummary s = deviation(ref, run, 0.01, &largest_m);
  EXPECT_NEAR(s.deviation.max_m, 0.02, kTol_m);
  EXPECT_NEAR(s.deviation.mean_m, 0.02 / 4.0, kTol_m);  // one of four fragments moved
  EXPECT_DOUBLE_EQ(s.deviation.deviated_share, 1.0 / 4.0);
  ASSERT_EQ(largest_m.size(), 4u);
  EXPECT_EQ(largest_m[0], 0.0);
  EXPECT_EQ(largest_m[1], 0.0);
  EXPECT_NEAR(largest_m[2], 0.02, kTol_m);
  EXPECT_EQ(largest_m[3], 0.0);
}

TEST(DeviationMetric, KeepsEachFragmentsLargestNotItsLast) {
  const Trajectory ref_run = make_run(2, 5);
  const TrajectoryRecord ref = record(ref_run);
  Trajectory run = ref_run;
  run[1][0].position_m += Eigen::Vector3d(0.03, 0.0, 0.04);  // 0.05 m
  run[4][0].position_m += Eigen::Vector3d(0.0, 0.01, 0.0);
  run[5][1].position_m += Eigen::Vector3d(-0.02, 0.0, 0.0);
  std::vector<double> largest_m;
  const RunSummary s = deviation(ref, run, 0.01, &largest_m);
  EXPECT_NEAR(largest_m[0], 0.05, kTol_m);
  EXPECT_NEAR(largest_m[1], 0.02, kTol_m);
  EXPECT_NEAR(s.deviation.max_m, 0.05, kTol_m);
  EXPECT_NEAR(s.deviation.mean_m, 0.035, kTol_m);
  EXPECT_DOUBLE_EQ(s.deviation.deviated_share, 1.0);
}

TEST(DeviationMetric, StepZeroIsCompared) {
  const Trajectory ref_run = make_run(2, 3);
  const TrajectoryRecord ref = record(ref_run);
  Trajectory run = ref_run;
  run[0][1].position_m.x() += 0.02;
  const RunSummary s = deviation(ref, run, 0.01);
  EXPECT_NEAR(s.deviation.max_m, 0.02, kTol_m);
  EXPECT_DOUBLE_EQ(s.deviation.deviated_share, 0.5);
}

TEST(DeviationMetric, ShiftBelowThresholdIsNotDeviated) {
  const Trajectory ref_run = make_run(3, 4);
  const TrajectoryRecord ref = record(ref_run);
  Trajectory run = ref_run;
  run[2][0].position_m.z() += 0.005;
  const RunSummary s = deviation(ref, run, 0.01);
  EXPECT_NEAR(s.deviation.max_m, 0.005, kTol_m);
  EXPECT_EQ(s.deviation.deviated_share, 0.0);
}

TEST(DeviationMetric, ShiftEqualToThresholdIsNotDeviated) {
  // Binary fractions keep the shift and its distance exact, so the boundary is tested exactly:
  // deviated means strictly more than the threshold.
  constexpr double kThreshold_m = 1.0 / 128.0;
  Trajectory ref_run = make_run(2, 2);
  ref_run[1][0].position_m = {1.0, 2.0, -4.0 - kThreshold_m};
  const TrajectoryRecord ref = record(ref_run);

  Trajectory at = ref_run;
  at[1][0].position_m.z() = -4.0;
  const RunSummary s_at = deviation(ref, at, kThreshold_m);
  EXPECT_EQ(s_at.deviation.max_m, kThreshold_m);
  EXPECT_EQ(s_at.deviation.deviated_share, 0.0);

  Trajectory past = ref_run;
  past[1][0].position_m.z() = -4.0 + kThreshold_m;
  const RunSummary s_past = deviation(ref, past, kThreshold_m);
  EXPECT_EQ(s_past.deviation.max_m, 2.0 * kThreshold_m);
  EXPECT_EQ(s_past.deviation.deviated_share, 0.5);
}

TEST(DeviationMetric, ShorterRunThanReferenceIsAccepted) {
  const TrajectoryRecord ref = record(make_run(3, 8));
  const RunSummary s = deviation(ref, make_run(3, 5), 0.01);
  EXPECT_EQ(s.deviation.max_m, 0.0);
}

TEST(DeviationMetric, ThrowsOnFragmentCountMismatch) {
  const TrajectoryRecord ref = record(make_run(3, 4));
  DeviationMetric metric(ref, 0.01);
  EXPECT_THROW(play(make_run(4, 4), metric), std::invalid_argument);
}

TEST(DeviationMetric, ThrowsOnMoreStepsThanReference) {
  const TrajectoryRecord ref = record(make_run(3, 4));
  DeviationMetric metric(ref, 0.01);
  EXPECT_THROW(play(make_run(3, 5), metric), std::invalid_argument);
}

TEST(DeviationMetric, ThrowsOnEmptyReference) {
  const TrajectoryRecord ref;
  DeviationMetric metric(ref, 0.01);
  EXPECT_THROW(play(make_run(0, 0), metric), std::invalid_argument);
}

}  // namespace
}  // namespace fragsim
