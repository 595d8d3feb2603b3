#pragma once
// One fragment as the simulation shows it after a step, in plain Eigen data, no engine handles.

#include <Eigen/Core>

#include "control/geometry/convex_shape.hpp"

namespace fragsim {

struct FragmentState {
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity_mps = Eigen::Vector3d::Zero();
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // body axes as columns, in world
  // A box of these half extents; with `shape`, the box about the centre of mass that holds it.
  Eigen::Vector3d half_extents_m = Eigen::Vector3d::Zero();
  const ConvexShape* shape = nullptr;  // null if the fragment is the box itself
  double mass_kg = 0.0;
  double radius_m = 0.0;  // bounding sphere about the centre of mass
  bool touched = false;   // had a contact (ground, wall, another fragment) in the last step
};

// A force a strategy applies to one fragment for the coming step.
struct AppliedForce {
  int fragment = 0;
  Eigen::Vector3d force_N = Eigen::Vector3d::Zero();
};

}  // namespace fragsim
