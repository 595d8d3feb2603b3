#pragma once
// Trajectory deviation (docs/method.md section 6) is each fragment's distance to the same fragment
// of the reference run (the `none` run of the same scene and seed) at the same step. A fragment's
// deviation is the largest such distance over the run, step 0 included.

#include <vector>

#include "metrics/run_summary.hpp"
#include "metrics/trajectory_record.hpp"
#include "sim/run_observer.hpp"

namespace fragsim {

class DeviationMetric final : public RunObserver {
 public:
  // The reference must outlive this metric; a fragment deviated when its deviation exceeds
  // threshold_m (MetricsDef::deviation_threshold_m).
  DeviationMetric(const TrajectoryRecord& reference, double threshold_m)
      : reference_(&reference), threshold_m_(threshold_m) {}

  // Throws std::invalid_argument if the reference has a different fragment count or fewer steps.
  void begin(const RunInfo& info, const StepSnapshot& initial) override;
  void observe(const StepSnapshot& snap) override;
  void fill(RunSummary& summary) const;

  // Each fragment's largest distance to its reference position so far.
  const std::vector<double>& largest_deviation_m() const { return largest_m_; }
  double threshold_m() const { return threshold_m_; }

 private:
  void compare(const StepSnapshot& snap);

  const TrajectoryRecord* reference_;
  double threshold_m_;
  std::vector<double> largest_m_;
};

}  // namespace fragsim
