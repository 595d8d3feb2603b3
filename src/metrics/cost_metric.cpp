#include "metrics/cost_metric.hpp"

#include <algorithm>
#include <cmath>

namespace fragsim {

void CostMetric::begin(const RunInfo& info, const StepSnapshot&) {
  physics_s_.clear();
  strategy_s_.clear();
  physics_s_.reserve(static_cast<std::size_t>(info.step_count));
  strategy_s_.reserve(static_cast<std::size_t>(info.step_count));
}

void CostMetric::observe(const StepSnapshot& snap) {
  physics_s_.push_back(snap.physics_s);
  strategy_s_.push_back(snap.strategy_s);
}

double CostMetric::quantile(std::vector<double> sample, double q) {
  if (sample.empty()) return 0.0;
  const auto rank =
      static_cast<std::size_t>(std::clamp(std::ceil(q * static_cast<double>(sample.size())) - 1.0,
                                          0.0, static_cast<double>(sample.size() - 1)));
  std::nth_element(sample.begin(), sample.begin() + static_cast<std::ptrdiff_t>(rank),
                   sample.end());
  return sample[rank];
}

void CostMetric::fill(RunSummary& s) const {
  s.cost.physics_ms_median = 1e3 * quantile(physics_s_, 0.5);
  s.cost.physics_ms_p95 = 1e3 * quantile(physics_s_, 0.95);
  s.cost.strategy_ms_median = 1e3 * quantile(strategy_s_, 0.5);
  s.cost.strategy_ms_p95 = 1e3 * quantile(strategy_s_, 0.95);
}

}  // namespace fragsim
