#pragma once
// What the simulation shows of one fragment after a step: plain Eigen data, no engine handles.

#include <Eigen/Core>

namespace fragsim {

struct FragmentState {
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity_mps = Eigen::Vector3d::Zero();
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // body axes as columns, in world
  Eigen::Vector3d half_extents_m = Eigen::Vector3d::Zero();
  double mass_kg = 0.0;
  double radius_m = 0.0;  // bounding sphere of the box
  bool touched = false;   // had a contact (ground, wall, another fragment) in the last step
};

// A force a strategy applies to one fragment for the coming step.
struct AppliedForce {
  int fragment = 0;
  Eigen::Vector3d force_N = Eigen::Vector3d::Zero();
};

}  // namespace fragsim
