#include "metrics/strategy_activity_metric.hpp"

#include <algorithm>
#include <numeric>

#include "geometry/depth_buffer.hpp"

namespace fragsim {

void StrategyActivityMetric::begin(const RunInfo& info, const StepSnapshot&) {
  dt_s_ = info.dt_s;
  candidates_.clear();
  near_m_.clear();
  forced_.assign(static_cast<std::size_t>(info.fragment_count), 0);
  capped_fragment_.assign(static_cast<std::size_t>(info.fragment_count), 0);
  capped_ = guarded_ = deferred_ = wall_contacts_ = 0;
  impulse_Ns_ = max_accel_mps2_ = 0.0;
}

void StrategyActivityMetric::observe(const StepSnapshot& snap) {
  candidates_.push_back(static_cast<int>(snap.candidates.size()));
  near_m_.push_back(snap.camera.near_m);
  capped_ += static_cast<int>(snap.capped.size());
  for (int i : snap.capped) capped_fragment_[static_cast<std::size_t>(i)] = 1;
  guarded_ += snap.guarded;
  deferred_ += snap.deferred;
  wall_contacts_ += snap.wall_contacts;
  for (const AppliedForce& f : snap.forces) {
    const double force_N = f.force_N.norm();
    impulse_Ns_ += force_N * dt_s_;
    const auto i = static_cast<std::size_t>(f.fragment);
    forced_[i] = 1;
    max_accel_mps2_ = std::max(max_accel_mps2_, force_N / snap.fragments[i].mass_kg);
  }
}

void StrategyActivityMetric::fill(RunSummary& summary) const {
  ActivityTotals& a = summary.activity;
  a.candidates_initial = candidates_.empty() ? 0 : candidates_.front();
  a.candidates_max =
      candidates_.empty() ? 0 : *std::max_element(candidates_.begin(), candidates_.end());
  a.candidate_steps = std::accumulate(candidates_.begin(), candidates_.end(), 0);
  a.capped_forces = capped_;
  a.guarded = guarded_;
  a.deferred = deferred_;
  a.forced_fragments = static_cast<int>(std::count(forced_.begin(), forced_.end(), 1));
  a.impulse_Ns = impulse_Ns_;
  a.max_accel_mps2 = max_accel_mps2_;
  a.wall_contacts = wall_contacts_;
  a.min_near_m = near_m_.empty() ? 0.0 : *std::min_element(near_m_.begin(), near_m_.end());
  a.depth_step_m =
      a.min_near_m > 0.0 ? depth_step_m(ref_distance_m_, a.min_near_m, depth_bits_) : 0.0;
}

}  // namespace fragsim
