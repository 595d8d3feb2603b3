#pragma once
// The camera at one instant: where the eye is, how it is oriented and its perspective frustum.
// Plain data shared by the simulation, the strategies and the metrics.

#include <Eigen/Core>
#include <cmath>

namespace fragsim {

inline constexpr double kPi = 3.14159265358979323846;

struct CameraPose {
  Eigen::Vector3d eye_m{0, 0, 0};
  Eigen::Vector3d right{1, 0, 0};     // r: screen x
  Eigen::Vector3d up{0, 1, 0};        // u: screen y
  Eigen::Vector3d forward{0, 0, -1};  // f: view direction
  double fovy_deg = 60.0;
  double aspect = 16.0 / 9.0;
  double near_m = 0.1;
  double far_m = 500.0;

  // Half extents of the frustum's cross-section at view depth `depth_m`.
  double half_height_at(double depth_m) const {
    return depth_m * std::tan(0.5 * fovy_deg * kPi / 180.0);
  }
  double half_width_at(double depth_m) const { return aspect * half_height_at(depth_m); }
  double near_half_height_m() const { return half_height_at(near_m); }
  double near_half_width_m() const { return half_width_at(near_m); }

  // World point to camera coordinates: x along right, y along up, z = depth along forward.
  Eigen::Vector3d to_camera(const Eigen::Vector3d& world_m) const {
    const Eigen::Vector3d d = world_m - eye_m;
    return {d.dot(right), d.dot(up), d.dot(forward)};
  }
  // World direction to camera axes (no translation).
  Eigen::Vector3d dir_to_camera(const Eigen::Vector3d& world_dir) const {
    return {world_dir.dot(right), world_dir.dot(up), world_dir.dot(forward)};
  }
  // Rotation whose columns are right, up, -forward (a right-handed camera frame).
  Eigen::Matrix3d rotation() const {
    Eigen::Matrix3d m;
    m.col(0) = right;
    m.col(1) = up;
    m.col(2) = -forward;
    return m;
  }
};

// One timed sample of a camera's motion: where the eye is and which way it looks. A recorded
// track (camera.csv, an engine's export) and the player model are lists of these.
struct CameraSample {
  double t_s = 0.0;
  Eigen::Vector3d eye_m{0, 0, 0};
  Eigen::Vector3d forward{0, 0, -1};
  Eigen::Vector3d up{0, 1, 0};
};

}  // namespace fragsim
