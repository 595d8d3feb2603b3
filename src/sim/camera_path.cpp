#include "sim/camera_path.hpp"

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

CameraPath::Place CameraPath::place_at(double t_s) const {
  const auto& w = def_.waypoints_m;
  if (w.size() == 1 || def_.speed_mps <= 0.0) return {0, 0.0};
  const double s = std::clamp(def_.speed_mps * std::max(t_s, 0.0), 0.0, arc_m_.back());
  auto it = std::upper_bound(arc_m_.begin(), arc_m_.end(), s);
  if (it == arc_m_.end()) return {w.size(), 0.0};
  const std::size_t i = static_cast<std::size_t>(it - arc_m_.begin());  // segment i-1 -> i
  const double len = arc_m_[i] - arc_m_[i - 1];
  return {i, len > 0.0 ? (s - arc_m_[i - 1]) / len : 0.0};
}

Eigen::Vector3d CameraPath::eye_at(double t_s) const {
  const auto& w = def_.waypoints_m;
  const Place p = place_at(t_s);
  if (p.i == 0) return w.front();
  if (p.i == w.size()) return w.back();
  return w[p.i - 1] + p.u * (w[p.i] - w[p.i - 1]);
}

Eigen::Vector3d CameraPath::look_at(double t_s) const {
  const auto& l = def_.look_at_m;
  if (l.size() == 1) return l.front();
  const Place p = place_at(t_s);
  if (p.i == 0) return l.front();
  if (p.i == l.size()) return l.back();
  return l[p.i - 1] + p.u * (l[p.i] - l[p.i - 1]);
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
  return pose_looking_at(def_, eye_at(t_s), look_at(t_s));
}

}  // namespace fragsim
