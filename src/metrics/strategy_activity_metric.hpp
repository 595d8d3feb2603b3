#pragma once
// What the strategy did, step by step: candidates (edge, fig. 4.3), forces, impulse and the largest
// imposed acceleration, cap and guard counts, wall contacts, the near distance in force.

#include <vector>

#include "metrics/run_summary.hpp"
#include "sim/run_observer.hpp"

namespace fragsim {

class StrategyActivityMetric final : public RunObserver {
 public:
  // depth_bits and ref_distance_m are those of the near-plane strategy's depth-step report.
  StrategyActivityMetric(int depth_bits, double ref_distance_m)
      : depth_bits_(depth_bits), ref_distance_m_(ref_distance_m) {}
  void begin(const RunInfo& info, const StepSnapshot& initial) override;
  void observe(const StepSnapshot& snap) override;
  void fill(RunSummary& summary) const;

  const std::vector<int>& candidates_per_step() const { return candidates_; }
  const std::vector<double>& near_per_step_m() const { return near_m_; }
  // Whether the acceleration cap ever reduced this fragment's force.
  bool was_capped(int fragment) const {
    return capped_fragment_[static_cast<std::size_t>(fragment)] != 0;
  }

 private:
  int depth_bits_;
  double ref_distance_m_;
  double dt_s_ = 0.0;
  std::vector<int> candidates_;
  std::vector<double> near_m_;
  std::vector<char> forced_;
  std::vector<char> capped_fragment_;
  int capped_ = 0;
  int guarded_ = 0;
  int deferred_ = 0;
  int wall_contacts_ = 0;
  double impulse_Ns_ = 0.0;
  double max_accel_mps2_ = 0.0;
};

}  // namespace fragsim
