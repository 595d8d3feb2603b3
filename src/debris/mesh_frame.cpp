#include "debris/mesh_frame.hpp"

namespace fragsim {

Eigen::Vector3d to_fragsim_frame(const MeshFrame& frame, const Eigen::Vector3d& file_point) {
  Eigen::Vector3d p = frame.unit_m * file_point;
  const bool left = frame.handedness == MeshHandedness::kLeft;
  if (frame.up == MeshUp::kY) return left ? Eigen::Vector3d(p.x(), p.y(), -p.z()) : p;
  return left ? Eigen::Vector3d(p.x(), p.z(), p.y()) : Eigen::Vector3d(p.x(), p.z(), -p.y());
}

}  // namespace fragsim
