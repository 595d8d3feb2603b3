#pragma once
// Records the camera as rendered at every snapshot (for camera.csv and for plots).

#include <vector>

#include "sim/run_observer.hpp"

namespace fragsim {

class CameraTrack final : public RunObserver {
 public:
  void begin(const RunInfo& info, const StepSnapshot& initial) override {
    poses_.clear();
    poses_.reserve(static_cast<std::size_t>(info.step_count) + 1);
    poses_.push_back(initial.camera);
  }
  void observe(const StepSnapshot& snap) override { poses_.push_back(snap.camera); }
  // poses()[k] is the camera at step k; poses()[0] at the explosion.
  const std::vector<CameraPose>& poses() const { return poses_; }

 private:
  std::vector<CameraPose> poses_;
};

}  // namespace fragsim
