#include "sim/sampled_camera.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cassert>

namespace fragsim {
namespace {

// The camera frame's rotation, with columns right, up, -forward (right-handed).
Eigen::Quaterniond orientation(const CameraSample& s) {
  Eigen::Matrix3d m;
  m.col(0) = s.forward.cross(s.up);
  m.col(1) = s.up;
  m.col(2) = -s.forward;
  return Eigen::Quaterniond(m).normalized();
}

}  // namespace

SampledCamera::SampledCamera(const CameraDef& def, std::vector<CameraSample> samples)
    : def_(def), samples_(std::move(samples)) {
  assert(!samples_.empty());
}

void SampledCamera::append(const CameraSample& s) {
  assert(s.t_s > samples_.back().t_s);
  samples_.push_back(s);
}

long SampledCamera::interval_at(double t_s) const {
  const auto it = std::upper_bound(samples_.begin(), samples_.end(), t_s,
                                   [](double t, const CameraSample& s) { return t < s.t_s; });
  return static_cast<long>(it - samples_.begin()) - 1;
}

Eigen::Vector3d SampledCamera::eye_at(double t_s) const {
  const long i = interval_at(t_s);
  if (i < 0) return samples_.front().eye_m;
  const auto k = static_cast<std::size_t>(i);
  if (k + 1 >= samples_.size()) return samples_.back().eye_m;
  const CameraSample& a = samples_[k];
  const CameraSample& b = samples_[k + 1];
  if (t_s == a.t_s) return a.eye_m;
  const double u = (t_s - a.t_s) / (b.t_s - a.t_s);
  return a.eye_m + u * (b.eye_m - a.eye_m);
}

Eigen::Vector3d SampledCamera::velocity_at(double t_s) const {
  const long i = interval_at(t_s);
  if (i < 0) return Eigen::Vector3d::Zero();
  const auto k = static_cast<std::size_t>(i);
  if (k + 1 >= samples_.size()) return Eigen::Vector3d::Zero();
  const CameraSample& a = samples_[k];
  const CameraSample& b = samples_[k + 1];
  return (b.eye_m - a.eye_m) / (b.t_s - a.t_s);
}

CameraPose SampledCamera::pose_at(double t_s) const {
  const long i = interval_at(t_s);
  const std::size_t k = i < 0 ? 0 : static_cast<std::size_t>(i);
  const CameraSample& a = samples_[k];
  if (i < 0 || k + 1 >= samples_.size() || t_s == a.t_s) {
    return pose_with_frustum(def_, eye_at(t_s), a.forward, a.up);
  }
  const CameraSample& b = samples_[k + 1];
  const double u = (t_s - a.t_s) / (b.t_s - a.t_s);
  const Eigen::Matrix3d m = orientation(a).slerp(u, orientation(b)).toRotationMatrix();
  return pose_with_frustum(def_, eye_at(t_s), -m.col(2), m.col(1));
}

}  // namespace fragsim
