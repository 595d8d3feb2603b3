#include "play/steered_camera.hpp"

#include <cmath>

namespace fragsim {
namespace {

CameraSample at_zero(CameraSample s) {
  s.t_s = 0.0;
  return s;
}

}  // namespace

SteeredCamera::SteeredCamera(const CameraDef& def, double dt_s, CameraSample first, NextSample next)
    : dt_s_(dt_s), next_(std::move(next)), track_(def, {at_zero(first)}) {}

void SteeredCamera::extend_past(double t_s) const {
  // The simulation asks at k dt exactly; the rounding guard keeps a time a hair past k dt at k.
  const long step = static_cast<long>(std::ceil(t_s / dt_s_ - 1e-6));
  while (static_cast<long>(track_.samples().size()) <= step + 1) {
    const int k = static_cast<int>(track_.samples().size());
    // The same product the simulation forms (k * dt), so the file's times are the run's.
    CameraSample s = next_(k, k * dt_s_);
    s.t_s = k * dt_s_;
    track_.append(s);
  }
}

Eigen::Vector3d SteeredCamera::eye_at(double t_s) const {
  extend_past(t_s);
  return track_.eye_at(t_s);
}

Eigen::Vector3d SteeredCamera::velocity_at(double t_s) const {
  extend_past(t_s);
  return track_.velocity_at(t_s);
}

CameraPose SteeredCamera::pose_at(double t_s) const {
  extend_past(t_s);
  return track_.pose_at(t_s);
}

}  // namespace fragsim
