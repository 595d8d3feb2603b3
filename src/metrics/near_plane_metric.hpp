#pragma once
// Near-plane intersections and camera hits (docs/method.md section 6). A fragment intersects the
// near plane in a step when its box (for a convex piece, the polytope itself, swept_box.hpp's
// HullSweep) meets the near rectangle at any time during the step's motion (swept_box.hpp), tested
// with that step's near distance; a camera hit is a touch of the camera body, reported by the
// physics' sensor or found by the same swept test (for a convex piece, with its hull's
// camera-aligned box, conservatively).
//
// In a frame with opacities (the `fade` strategy), a fragment invisible (opacity 0) at the start or
// the end of the step in which it meets the near rectangle is drawn neither cut nor whole, so it
// is no near-plane intersection; it is counted among the vanished (vanished_metric.hpp) instead.
// Camera hits still count, as the fragment still flies into the camera's body.

#include <vector>

#include "geometry/swept_box.hpp"
#include "metrics/run_summary.hpp"
#include "sim/run_observer.hpp"

namespace fragsim {

class NearPlaneMetric final : public RunObserver {
 public:
  void begin(const RunInfo& info, const StepSnapshot& initial) override;
  void observe(const StepSnapshot& snap) override;
  void fill(RunSummary& summary) const;

  // Fragments meeting the near rectangle in each step (index = step - 1).
  const std::vector<int>& per_step() const { return per_step_; }
  // The fragments counted in the last observed step (the report's viewer highlights them).
  const std::vector<int>& last_step_fragments() const { return last_step_; }
  bool intersected(int fragment) const {
    return near_hit_[static_cast<std::size_t>(fragment)] != 0;
  }
  bool camera_hit(int fragment) const { return body_hit_[static_cast<std::size_t>(fragment)] != 0; }
  // Whether the fragment met the near rectangle while invisible (so it is not intersected()).
  bool crossed_invisible(int fragment) const {
    return near_invisible_[static_cast<std::size_t>(fragment)] != 0;
  }

 private:
  std::vector<SweepEnd> prev_;
  // The last snapshot's convex pieces and camera, for the exact test (boxes are not copied).
  std::vector<FragmentState> prev_state_;
  CameraPose prev_camera_;
  HullSweep hull_sweep_;
  std::vector<char> near_hit_;
  std::vector<char> body_hit_;
  std::vector<char> near_invisible_;
  std::vector<float> prev_opacity_;  // each fragment's in the last snapshot (1 is opaque)
  std::vector<int> per_step_;
  std::vector<int> last_step_;
  int fragment_steps_ = 0;
};

}  // namespace fragsim
