#include "play/steered_camera.hpp"

#include <cassert>

namespace fragsim {
namespace {

CameraSample at_zero(CameraSample s) {
  s.t_s = 0.0;
  return s;
}

}  // namespace

SteeredCamera::SteeredCamera(const CameraDef& def, double dt_s, CameraSample first)
    : dt_s_(dt_s), track_(def, {at_zero(first)}) {}

double SteeredCamera::next_t_s() const {
  // The same product the run forms (k * dt), so the file's times are the run's.
  return static_cast<int>(track_.samples().size()) * dt_s_;
}

void SteeredCamera::steer(CameraSample s) {
  s.t_s = next_t_s();
  track_.append(s);
}

Eigen::Vector3d SteeredCamera::eye_at(double t_s) const {
  return track_.eye_at(t_s);
}

Eigen::Vector3d SteeredCamera::velocity_at(double t_s) const {
  // The velocity over the step from t_s needs the sample at its end, as past its last sample a
  // track stands still, which the player did not ask for.
  assert(t_s < track_.samples().back().t_s);
  return track_.velocity_at(t_s);
}

CameraPose SteeredCamera::pose_at(double t_s) const {
  return track_.pose_at(t_s);
}

}  // namespace fragsim
