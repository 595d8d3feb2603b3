#include "metrics/deviation_metric.hpp"

#include <algorithm>
#include <cassert>
#include <stdexcept>
#include <string>

namespace fragsim {

void DeviationMetric::begin(const RunInfo& info, const StepSnapshot& initial) {
  if (info.fragment_count != reference_->fragments()) {
    throw std::invalid_argument("deviation: run '" + info.strategy + "' has " +
                                std::to_string(info.fragment_count) + " fragments, the reference " +
                                std::to_string(reference_->fragments()));
  }
  // The reference holds steps() snapshots, step 0 included, so it covers steps() - 1 steps.
  if (info.step_count >= reference_->steps()) {
    throw std::invalid_argument("deviation: run '" + info.strategy + "' has " +
                                std::to_string(info.step_count) + " steps, the reference " +
                                std::to_string(std::max(reference_->steps() - 1, 0)));
  }
  largest_m_.assign(static_cast<std::size_t>(info.fragment_count), 0.0);
  compare(initial);
}

void DeviationMetric::observe(const StepSnapshot& snap) {
  compare(snap);
}

void DeviationMetric::compare(const StepSnapshot& snap) {
  assert(snap.step < reference_->steps());
  assert(snap.fragments.size() == largest_m_.size());
  const std::span<const Eigen::Vector3d> ref_m = reference_->at_step(snap.step);
  for (std::size_t i = 0; i < largest_m_.size(); ++i) {
    largest_m_[i] = std::max(largest_m_[i], (snap.fragments[i].position_m - ref_m[i]).norm());
  }
}

void DeviationMetric::fill(RunSummary& s) const {
  if (largest_m_.empty()) {
    s.deviation = {};
    return;
  }
  double sum_m = 0.0;
  double max_m = 0.0;
  int deviated = 0;
  for (double d : largest_m_) {
    sum_m += d;
    max_m = std::max(max_m, d);
    if (d > threshold_m_) ++deviated;
  }
  const auto n = static_cast<double>(largest_m_.size());
  s.deviation.mean_m = sum_m / n;
  s.deviation.max_m = max_m;
  s.deviation.deviated_share = deviated / n;
}

}  // namespace fragsim
