#include "metrics/vanished_metric.hpp"

#include <algorithm>

namespace fragsim {

namespace {

constexpr float kHalf = 0.5f;

bool in_view(const CameraPose& camera, const FragmentState& f) {
  return camera.frustum().sphere_may_show(camera.to_camera(f.position_m), f.radius_m);
}

}  // namespace

void VanishedMetric::begin(const RunInfo& info, const StepSnapshot& initial) {
  const auto n = static_cast<std::size_t>(info.fragment_count);
  prev_opacity_.assign(n, 1.0f);
  faded_.assign(n, 0);
  if (!initial.opacity.empty()) {
    std::copy(initial.opacity.begin(), initial.opacity.end(), prev_opacity_.begin());
  }
}

void VanishedMetric::observe(const StepSnapshot& snap) {
  if (snap.opacity.empty()) {  // opaque, so nothing fades
    std::fill(prev_opacity_.begin(), prev_opacity_.end(), 1.0f);
    return;
  }
  for (std::size_t i = 0; i < snap.fragments.size(); ++i) {
    const float opacity = snap.opacity[i];
    // Seen to fade means in view in the frame where it has dropped below half. One that drops as it
    // leaves the view has left the picture, as the thesis wants.
    if (!faded_[i] && prev_opacity_[i] >= kHalf && opacity < kHalf &&
        in_view(snap.camera, snap.fragments[i])) {
      faded_[i] = 1;
    }
    prev_opacity_[i] = opacity;
  }
}

void VanishedMetric::fill(RunSummary& s, const NearPlaneMetric& near) const {
  int count = 0;
  for (std::size_t i = 0; i < faded_.size(); ++i) {
    if (faded_[i] || near.crossed_invisible(static_cast<int>(i))) ++count;
  }
  s.intersections.vanished_fragments = count;
}

}  // namespace fragsim
