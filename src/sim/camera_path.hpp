#pragma once
// The camera's scripted motion (camera.mode = path) runs along the waypoints at constant speed from
// t = 0, stopping at the last one, looking at one fixed point or, with one look-at point per
// waypoint, at the point interpolated along the path in step with the eye (so the view pans).

#include <vector>

#include "sim/camera_motion.hpp"

namespace fragsim {

class CameraPath final : public CameraMotion {
 public:
  explicit CameraPath(const CameraDef& def);
  Eigen::Vector3d eye_at(double t_s) const override;
  Eigen::Vector3d velocity_at(double t_s) const override;
  // `up` is world y made orthogonal to the view.
  CameraPose pose_at(double t_s) const override;
  Eigen::Vector3d look_at(double t_s) const;

 private:
  // Where on the path the eye is at t_s, as segment i - 1 -> i at share u (i = 0 before the first
  // point or with a single one, i = size at the end).
  struct Place {
    std::size_t i;
    double u;
  };
  Place place_at(double t_s) const;

  CameraDef def_;
  std::vector<double> arc_m_;  // arc length at each waypoint
};

}  // namespace fragsim
