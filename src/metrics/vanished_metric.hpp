#pragma once
// Vanished fragments are what a fade costs (the thesis's complaint that debris "suddenly
// disappears"). A fragment vanishes when its opacity drops below one half between two frames
// and, in the frame where it is below, it is in the view (its bounding sphere not wholly outside
// the frustum, near plane included), or when it meets the near rectangle invisible
// (near_plane_metric); each fragment counts once. A run without opacities (every strategy but
// fade) has none.

#include <vector>

#include "metrics/near_plane_metric.hpp"
#include "metrics/run_summary.hpp"
#include "sim/run_observer.hpp"

namespace fragsim {

class VanishedMetric final : public RunObserver {
 public:
  void begin(const RunInfo& info, const StepSnapshot& initial) override;
  void observe(const StepSnapshot& snap) override;
  // Sets vanished_fragments to the fragments that faded out in view, with those `near` saw cross
  // the near plane invisible.
  void fill(RunSummary& summary, const NearPlaneMetric& near) const;

  // Whether the fragment faded below one half in view (without the near-plane crossings).
  bool faded_in_view(int fragment) const { return faded_[static_cast<std::size_t>(fragment)] != 0; }

 private:
  std::vector<float> prev_opacity_;
  std::vector<char> faded_;
};

}  // namespace fragsim
