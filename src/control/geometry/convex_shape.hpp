#pragma once
// A convex piece of debris in its body frame (origin at its centre of mass, axes those of the
// body). One shape may be shared by many fragments and never changes once built, so fragments hold
// a plain pointer to it (FragmentState::shape) and the debris list owns it.

#include <Eigen/Core>
#include <vector>

namespace fragsim {

struct ConvexShape {
  std::vector<Eigen::Vector3d> vertices_m;
  // Each face a loop of vertex indices, counter-clockwise seen from outside (as ODE's
  // dCreateConvex and the renderer take them); the faces' outward unit normals and offsets,
  // n . x <= d on and inside the piece, in the same order.
  std::vector<std::vector<int>> faces;
  std::vector<Eigen::Vector3d> normals;
  std::vector<double> offsets_m;
  double volume_m3 = 0.0;
  // The inertia tensor about the centre of mass, divided by the mass (m^2). The tensor of a piece
  // of mass M is M times this, so one shape serves every density.
  Eigen::Matrix3d inertia_per_kg_m2 = Eigen::Matrix3d::Zero();
  double radius_m = 0.0;  // the farthest vertex from the centre of mass
  // Per body axis the largest |coordinate| of a vertex, giving the box about the centre of mass
  // that holds the piece, which every test written for boxes can use as a conservative bound.
  Eigen::Vector3d half_extents_m = Eigen::Vector3d::Zero();
};

}  // namespace fragsim
