#pragma once
// A camera whose motion is decided as the run goes: a track (SampledCamera) that grows by one
// sample per step, asked of the caller the first time the simulation needs it. The samples are the
// recorded flight: replayed as camera.mode = track they give the run the same poses and
// velocities, bit for bit.

#include <functional>
#include <vector>

#include "sim/camera_motion.hpp"
#include "sim/sampled_camera.hpp"

namespace fragsim {

class SteeredCamera final : public CameraMotion {
 public:
  // The sample at step k's time, k dt, given the step index k >= 1.
  using NextSample = std::function<CameraSample(int step, double t_s)>;

  // `first` is the pose at t = 0 (its time is set to 0).
  SteeredCamera(const CameraDef& def, double dt_s, CameraSample first, NextSample next);

  Eigen::Vector3d eye_at(double t_s) const override;
  Eigen::Vector3d velocity_at(double t_s) const override;
  CameraPose pose_at(double t_s) const override;

  // Every sample made so far, from t = 0.
  const std::vector<CameraSample>& samples() const { return track_.samples(); }

 private:
  // Makes the samples up to the one after t_s's step: the velocity over the step starting at t_s
  // needs it.
  void extend_past(double t_s) const;

  double dt_s_;
  NextSample next_;
  // The simulation sees a const camera; the samples it asks for are made on demand.
  mutable SampledCamera track_;
};

}  // namespace fragsim
