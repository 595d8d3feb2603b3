#pragma once
// A convex fragment (FragmentState::shape) seen from a camera, its vertices in camera coordinates
// and its exact extents along the camera's axes, the counterpart of camera_box.hpp for hulls. Box
// fragments keep camera_box.hpp, so their results stay the same to the bit.

#include <Eigen/Core>
#include <algorithm>
#include <cassert>
#include <vector>

#include "control/geometry/camera_pose.hpp"
#include "control/geometry/fragment_state.hpp"

namespace fragsim {

// The world-to-camera rotation times the body's (body-frame vectors to camera axes).
inline Eigen::Matrix3d body_to_camera(const CameraPose& camera, const Eigen::Matrix3d& rotation) {
  Eigen::Matrix3d to_cam;
  to_cam.row(0) = camera.right.transpose();
  to_cam.row(1) = camera.up.transpose();
  to_cam.row(2) = camera.forward.transpose();
  return to_cam * rotation;
}

// How far the hull reaches from its centre of mass along +x, +y, +z of the camera (plus_m) and
// along -x, -y, -z (minus_m), its camera-aligned bounding box, exact (attained by a vertex) and
// inside the one its body box gives. (A fragment's extents, as CameraBox is its box.)
struct CameraExtents {
  Eigen::Vector3d plus_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d minus_m = Eigen::Vector3d::Zero();
};

inline CameraExtents hull_camera_extents(const CameraPose& camera, const FragmentState& f) {
  assert(f.shape && !f.shape->vertices_m.empty());
  const Eigen::Matrix3d m = body_to_camera(camera, f.rotation);
  CameraExtents e;
  bool first = true;
  for (const Eigen::Vector3d& v : f.shape->vertices_m) {
    const Eigen::Vector3d w = m * v;
    if (first) {
      e.plus_m = w;
      e.minus_m = -w;
      first = false;
    } else {
      e.plus_m = e.plus_m.cwiseMax(w);
      e.minus_m = e.minus_m.cwiseMax(-w);
    }
  }
  return e;
}

// The hull's vertices in camera coordinates, written to `out` (resized; its capacity is reused).
inline void hull_camera_vertices(const CameraPose& camera, const FragmentState& f,
                                 std::vector<Eigen::Vector3d>& out) {
  assert(f.shape);
  const Eigen::Matrix3d m = body_to_camera(camera, f.rotation);
  const Eigen::Vector3d c = camera.to_camera(f.position_m);
  out.resize(f.shape->vertices_m.size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = c + m * f.shape->vertices_m[i];
}

}  // namespace fragsim
