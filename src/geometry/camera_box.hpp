#pragma once
// A fragment's box seen from a camera, its centre, body axes and half axes in camera coordinates,
// its 8 corners, and its extents along the camera's axes. The occlusion raster, the renderer and
// the swept near-plane tests all take the box from here.

#include <Eigen/Core>
#include <array>
#include <cstddef>

#include "control/geometry/camera_pose.hpp"
#include "control/geometry/fragment_state.hpp"

namespace fragsim {

// A fragment's box in camera coordinates (not a camera, but the fragment as the camera sees it).
struct CameraBox {
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();
  Eigen::Matrix3d dirs = Eigen::Matrix3d::Identity();     // the body axes (unit columns)
  Eigen::Matrix3d half_axes_m = Eigen::Matrix3d::Zero();  // dirs scaled by the half extents

  // A non-finite state is reported by the simulation's own checks; callers must not draw it.
  bool finite() const { return centre_m.allFinite() && half_axes_m.allFinite(); }

  // Corner i has the sign of half axis k given by bit k of i, so corner i and corner i | (1 << k)
  // share the edge along axis k. The axes are added in order 0, 1, 2 (the order fixes rounding).
  Eigen::Vector3d corner(int i) const {
    Eigen::Vector3d p = centre_m;
    for (int k = 0; k < 3; ++k) {
      if ((i >> k) & 1) {
        p += half_axes_m.col(k);
      } else {
        p -= half_axes_m.col(k);
      }
    }
    return p;
  }
  std::array<Eigen::Vector3d, 8> corners() const {
    std::array<Eigen::Vector3d, 8> out;
    for (int i = 0; i < 8; ++i) out[static_cast<std::size_t>(i)] = corner(i);
    return out;
  }
};

inline CameraBox camera_box(const CameraPose& camera, const FragmentState& f) {
  CameraBox b;
  b.centre_m = camera.to_camera(f.position_m);
  for (int k = 0; k < 3; ++k) {
    b.dirs.col(k) = camera.dir_to_camera(f.rotation.col(k));
    b.half_axes_m.col(k) = b.dirs.col(k) * f.half_extents_m[k];
  }
  return b;
}

// Half extents along the camera's right, up and forward axes of a fragment's (rotated) box. Its
// own product rather than |half_axes_m| summed per row, as the swept tests' results rest on this
// one and the two sum in different orders.
inline Eigen::Vector3d camera_aligned_extents(const CameraPose& camera, const FragmentState& f) {
  Eigen::Matrix3d to_cam;
  to_cam.row(0) = camera.right.transpose();
  to_cam.row(1) = camera.up.transpose();
  to_cam.row(2) = camera.forward.transpose();
  return (to_cam * f.rotation).cwiseAbs() * f.half_extents_m;
}

}  // namespace fragsim
