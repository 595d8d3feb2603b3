#pragma once
// The camera's scripted motion: along the waypoints at constant speed, looking at a fixed point.

#include <vector>

#include "sim/camera_pose.hpp"
#include "sim/scene.hpp"

namespace fragsim {

class CameraPath {
 public:
  explicit CameraPath(const CameraDef& def);
  Eigen::Vector3d eye_at(double t_s) const;
  Eigen::Vector3d velocity_at(double t_s) const;
  // The pose at t_s with the scene's frustum; `up` is world y made orthogonal to the view.
  CameraPose pose_at(double t_s) const;

 private:
  CameraDef def_;
  std::vector<double> arc_m_;  // arc length at each waypoint
};

}  // namespace fragsim
