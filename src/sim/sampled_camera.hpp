#pragma once
// A camera given as timed samples (a replayed track, the player model). Between two samples the
// eye moves on the straight line between them and the orientation turns by quaternion slerp; the
// velocity over a sample interval is that interval's (the distance over the time). Before the
// first sample the camera holds the first pose and after the last the last one, standing still:
// a track says nothing of what the camera did outside it.

#include <vector>

#include "sim/camera_motion.hpp"

namespace fragsim {

class SampledCamera final : public CameraMotion {
 public:
  // `samples` must be non-empty, strictly increasing in time, with unit orthogonal bases
  // (camera_track_file.hpp checks files for that).
  SampledCamera(const CameraDef& def, std::vector<CameraSample> samples);
  Eigen::Vector3d eye_at(double t_s) const override;
  Eigen::Vector3d velocity_at(double t_s) const override;
  // At a sample's own time, exactly that sample's vectors (right = forward x up).
  CameraPose pose_at(double t_s) const override;

  // A camera driven live grows sample by sample (src/play); `s` must come after the last one.
  void append(const CameraSample& s);
  const std::vector<CameraSample>& samples() const { return samples_; }

 private:
  // The interval [samples_[i], samples_[i + 1]) holding t_s; -1 before the first sample, or the
  // last index at or after the last.
  long interval_at(double t_s) const;

  CameraDef def_;
  std::vector<CameraSample> samples_;
};

}  // namespace fragsim
