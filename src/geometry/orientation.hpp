#pragma once
// A body's orientation as a unit quaternion, the form trajectories.csv and the bake
// (report/gltf_bake.hpp) write, from the rotation matrix a snapshot holds (FragmentState::rotation,
// body axes as columns in world; CameraPose::rotation()).

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace fragsim {

// The unit quaternion of the rotation whose columns are `axes` (orthonormal to rounding, as ODE's
// matrices are), with w >= 0, so it is always the same one of every rotation's two quaternions.
inline Eigen::Quaterniond orientation_quaternion(const Eigen::Matrix3d& axes) {
  Eigen::Quaterniond q(axes);
  q.normalize();
  if (q.w() < 0) q.coeffs() = -q.coeffs();
  return q;
}

}  // namespace fragsim
