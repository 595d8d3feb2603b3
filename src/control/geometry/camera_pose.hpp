#pragma once
// The camera at one instant: where the eye is, how it is oriented and its perspective frustum
// (whose geometry is frustum.hpp's), and the world-to-camera change of coordinates. Plain data
// shared by the simulation, the strategies and the metrics.

#include <Eigen/Core>

#include "control/geometry/frustum.hpp"
#include "control/geometry/vec3_sums.hpp"

namespace fragsim {

// The camera at one instant, frustum included, as strategies, metrics and the renderer see it (a
// scene's CameraDef says how it moves; a CameraSample is a recorded instant, without frustum).
struct CameraPose {
  Eigen::Vector3d eye_m{0, 0, 0};
  Eigen::Vector3d right{1, 0, 0};     // r, screen x
  Eigen::Vector3d up{0, 1, 0};        // u, screen y
  Eigen::Vector3d forward{0, 0, -1};  // f, view direction
  double fovy_deg = kDefaultFrustum.fovy_deg;
  double aspect = kDefaultFrustum.aspect;
  double near_m = kDefaultFrustum.near_m;
  double far_m = kDefaultFrustum.far_m;

  Frustum frustum() const { return Frustum(fovy_deg, aspect, near_m, far_m); }

  // Half extents of the frustum's cross-section at view depth `depth_m`; the same bits as
  // frustum()'s, without building one (strategies call these per fragment).
  double half_height_at(double depth_m) const { return depth_m * tan_half_fovy(fovy_deg); }
  double half_width_at(double depth_m) const { return aspect * half_height_at(depth_m); }
  double near_half_height_m() const { return half_height_at(near_m); }
  double near_half_width_m() const { return half_width_at(near_m); }

  // World point to camera coordinates (x along right, y along up, z = depth along forward).
  Eigen::Vector3d to_camera(const Eigen::Vector3d& world_m) const {
    const Eigen::Vector3d d = world_m - eye_m;
    return {dot3(d, right), dot3(d, up), dot3(d, forward)};
  }
  // World direction to camera axes (no translation).
  Eigen::Vector3d dir_to_camera(const Eigen::Vector3d& world_dir) const {
    return {dot3(world_dir, right), dot3(world_dir, up), dot3(world_dir, forward)};
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

// One timed sample of a camera's motion (where the eye is and which way it looks). A recorded track
// (camera.csv, an engine's export) and the player model are lists of these; the frustum is the
// scene's, so it is not here.
struct CameraSample {
  double t_s = 0.0;
  Eigen::Vector3d eye_m{0, 0, 0};
  Eigen::Vector3d forward{0, 0, -1};
  Eigen::Vector3d up{0, 1, 0};
};

}  // namespace fragsim
