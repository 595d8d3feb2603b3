#include "sim/camera_path.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace fragsim {

CameraPath::CameraPath(const CameraDef& def) : def_(def) {
  arc_m_.reserve(def_.waypoints_m.size());
  double s = 0.0;
  for (std::size_t i = 0; i < def_.waypoints_m.size(); ++i) {
    if (i > 0) s += (def_.waypoints_m[i] - def_.waypoints_m[i - 1]).norm();
    arc_m_.push_back(s);
  }
}

Eigen::Vector3d CameraPath::eye_at(double t_s) const {
  const auto& w = def_.waypoints_m;
  if (w.size() == 1 || def_.speed_mps <= 0.0) return w.front();
  const double s = std::clamp(def_.speed_mps * std::max(t_s, 0.0), 0.0, arc_m_.back());
  auto it = std::upper_bound(arc_m_.begin(), arc_m_.end(), s);
  if (it == arc_m_.end()) return w.back();
  const std::size_t i = static_cast<std::size_t>(it - arc_m_.begin());  // segment i-1 -> i
  const double len = arc_m_[i] - arc_m_[i - 1];
  const double u = len > 0.0 ? (s - arc_m_[i - 1]) / len : 0.0;
  return w[i - 1] + u * (w[i] - w[i - 1]);
}

Eigen::Vector3d CameraPath::velocity_at(double t_s) const {
  const auto& w = def_.waypoints_m;
  if (w.size() == 1 || def_.speed_mps <= 0.0) return Eigen::Vector3d::Zero();
  const double s = def_.speed_mps * std::max(t_s, 0.0);
  if (s >= arc_m_.back()) return Eigen::Vector3d::Zero();
  auto it = std::upper_bound(arc_m_.begin(), arc_m_.end(), s);
  const std::size_t i = static_cast<std::size_t>(it - arc_m_.begin());
  const Eigen::Vector3d seg = w[i] - w[i - 1];
  const double len = seg.norm();
  return len > 0.0 ? Eigen::Vector3d(def_.speed_mps * seg / len) : Eigen::Vector3d::Zero();
}

CameraPose CameraPath::pose_at(double t_s) const {
  CameraPose pose;
  pose.eye_m = eye_at(t_s);
  Eigen::Vector3d f = def_.look_at_m.front() - pose.eye_m;
  // Scene validation keeps look_at away from the path; this guards the instant the eye reaches it.
  if (f.norm() < 1e-9) f = Eigen::Vector3d(0, 0, -1);
  pose.forward = f.normalized();
  Eigen::Vector3d world_up(0, 1, 0);
  if (std::abs(pose.forward.dot(world_up)) > 0.999) world_up = Eigen::Vector3d(0, 0, 1);
  pose.right = pose.forward.cross(world_up).normalized();
  pose.up = pose.right.cross(pose.forward);
  pose.fovy_deg = def_.fovy_deg;
  pose.aspect = def_.aspect;
  pose.near_m = def_.near_m;
  pose.far_m = def_.far_m;
  return pose;
}

}  // namespace fragsim
