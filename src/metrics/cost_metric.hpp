#pragma once
// Wall time per step of the physics and of the strategy, apart, as median and 95th percentile.
// The only metric that differs between two runs of the same scene.

#include <vector>

#include "metrics/run_summary.hpp"
#include "sim/run_observer.hpp"

namespace fragsim {

class CostMetric final : public RunObserver {
 public:
  void begin(const RunInfo& info, const StepSnapshot& initial) override;
  void observe(const StepSnapshot& snap) override;
  void fill(RunSummary& summary) const;

  const std::vector<double>& physics_s() const { return physics_s_; }
  const std::vector<double>& strategy_s() const { return strategy_s_; }

  // The q-quantile (0..1) by nearest rank; 0 for an empty sample.
  static double quantile(std::vector<double> sample, double q);

 private:
  std::vector<double> physics_s_;
  std::vector<double> strategy_s_;
};

}  // namespace fragsim
