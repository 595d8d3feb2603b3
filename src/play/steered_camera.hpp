#pragma once
// A camera whose motion is decided as the run goes, a track (SampledCamera) that the player's loop
// grows by one sample per step, ahead of the run (run.hpp says how far). The samples are the
// recorded flight, and replayed as camera.mode = track they give the run the same poses and
// velocities, bit for bit.

#include <vector>

#include "sim/camera_motion.hpp"
#include "sim/sampled_camera.hpp"

namespace fragsim {

class SteeredCamera final : public CameraMotion {
 public:
  // `first` is the pose at t = 0 (its time is set to 0).
  SteeredCamera(const CameraDef& def, double dt_s, CameraSample first);

  // The time of the next sample, k dt for the k-th (from 0).
  double next_t_s() const;
  // Appends `s` as the next sample, stamped next_t_s().
  void steer(CameraSample s);

  Eigen::Vector3d eye_at(double t_s) const override;
  Eigen::Vector3d velocity_at(double t_s) const override;
  CameraPose pose_at(double t_s) const override;

  // Every sample made so far, from t = 0.
  const std::vector<CameraSample>& samples() const { return track_.samples(); }

 private:
  double dt_s_;
  SampledCamera track_;
};

}  // namespace fragsim
