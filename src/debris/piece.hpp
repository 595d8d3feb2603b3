#pragma once
// What the object breaks into, before the blast, as each piece's place and shape. The grid of equal
// cubes, Voronoi cells of the object's box and pieces read from a mesh file all end as a list of
// these, which the explosion gives velocities and the world turns into bodies.

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "control/geometry/convex_shape.hpp"

namespace fragsim {

struct Piece {
  // Its centre of mass relative to the object's centre (object.centre_m), and its body axes as
  // columns, which place the shape's body frame in the object's frame.
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  // A box of these half extents when `shape` is null (the grid's cubes stay ODE boxes); else the
  // hull, and half_extents_m is shape->half_extents_m.
  Eigen::Vector3d half_extents_m = Eigen::Vector3d::Zero();
  std::shared_ptr<const ConvexShape> shape;
  double mass_kg = 0.0;
};

}  // namespace fragsim
