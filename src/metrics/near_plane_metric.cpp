#include "metrics/near_plane_metric.hpp"

#include <algorithm>

namespace fragsim {

void NearPlaneMetric::begin(const RunInfo& info, const StepSnapshot& initial) {
  const auto n = static_cast<std::size_t>(info.fragment_count);
  prev_.resize(n);
  prev_state_.assign(n, FragmentState{});
  for (std::size_t i = 0; i < n; ++i) {
    prev_[i] = sweep_end(initial.camera, initial.fragments[i]);
    if (initial.fragments[i].shape) prev_state_[i] = initial.fragments[i];
  }
  prev_camera_ = initial.camera;
  near_hit_.assign(n, 0);
  body_hit_.assign(n, 0);
  near_invisible_.assign(n, 0);
  prev_opacity_.assign(n, 1.0f);
  per_step_.clear();
  per_step_.reserve(static_cast<std::size_t>(info.step_count));
  last_step_.clear();
  fragment_steps_ = 0;
}

void NearPlaneMetric::observe(const StepSnapshot& snap) {
  int count = 0;
  last_step_.clear();
  const bool translucent = !snap.opacity.empty();
  for (std::size_t i = 0; i < snap.fragments.size(); ++i) {
    const FragmentState& f = snap.fragments[i];
    const SweepEnd now = sweep_end(snap.camera, f);
    const float opacity = translucent ? snap.opacity[i] : 1.0f;
    // The hull's box first, as it is cheap and clears all but the pieces at the lens.
    if (sweep_meets_near_rectangle(prev_[i], now) &&
        (!f.shape ||
         hull_sweep_.meets_near_rectangle(prev_camera_, prev_state_[i], snap.camera, f))) {
      if (std::min(prev_opacity_[i], opacity) > 0.0f) {
        ++count;
        near_hit_[i] = 1;
        last_step_.push_back(static_cast<int>(i));
      } else {
        near_invisible_[i] = 1;
      }
    }
    prev_opacity_[i] = opacity;
    if (!body_hit_[i] && sweep_meets_camera_body(prev_[i], now, snap.camera_body_half_m)) {
      body_hit_[i] = 1;
    }
    prev_[i] = now;
    if (f.shape) prev_state_[i] = f;
  }
  prev_camera_ = snap.camera;
  for (int f : snap.camera_hits) body_hit_[static_cast<std::size_t>(f)] = 1;
  per_step_.push_back(count);
  fragment_steps_ += count;
}

void NearPlaneMetric::fill(RunSummary& s) const {
  s.intersections.near_fragment_steps = fragment_steps_;
  s.intersections.near_fragments =
      static_cast<int>(std::count(near_hit_.begin(), near_hit_.end(), 1));
  s.intersections.camera_hit_fragments =
      static_cast<int>(std::count(body_hit_.begin(), body_hit_.end(), 1));
}

}  // namespace fragsim
