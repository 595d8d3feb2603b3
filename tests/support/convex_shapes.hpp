#pragma once
// Convex pieces with every field in closed form, for tests of code that takes
// FragmentState::shape: a regular tetrahedron, a box (a cube when its half extents are equal) and a
// thin triangular slab. Faces are counter-clockwise seen from outside (ConvexShape's convention);
// tests/geometry/convex_shapes_test.cpp checks them against their vertices.

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>

#include "geometry/convex_shape.hpp"
#include "geometry/fragment_state.hpp"

namespace fragsim::test {

// The regular tetrahedron with vertices a (1, 1, 1), a (1, -1, -1), a (-1, 1, -1), a (-1, -1, 1):
// every other corner of the cube of half side a, so its centroid is the origin. Edge
// L = 2 sqrt(2) a; circumradius R = sqrt(3) a (vertex 0 lies along (1, 1, 1)); each face lies R / 3
// from the centre, across from a vertex; volume 8 a^3 / 3 (a third of the cube's); inertia
// L^2 / 20 = 2 a^2 / 5 per kg about every axis.
inline ConvexShape regular_tetrahedron(double a_m) {
  ConvexShape s;
  s.vertices_m = {{a_m, a_m, a_m}, {a_m, -a_m, -a_m}, {-a_m, a_m, -a_m}, {-a_m, -a_m, a_m}};
  // Face i is the one across from vertex i; its outward normal is minus vertex i's direction.
  s.faces = {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}};
  const double k = 1.0 / std::sqrt(3.0);
  for (const Eigen::Vector3d& v : s.vertices_m) s.normals.push_back(-k * v / a_m);
  s.offsets_m.assign(4, a_m * k);
  s.volume_m3 = 8.0 * a_m * a_m * a_m / 3.0;
  s.inertia_per_kg_m2 = Eigen::Matrix3d::Identity() * (0.4 * a_m * a_m);
  s.radius_m = std::sqrt(3.0) * a_m;
  s.half_extents_m = Eigen::Vector3d::Constant(a_m);
  return s;
}

// The box of half extents h as a hull. Vertex i has the sign of axis k given by bit k of i, as
// CameraBox::corner numbers a box's corners.
inline ConvexShape box_hull(const Eigen::Vector3d& h_m) {
  ConvexShape s;
  for (int i = 0; i < 8; ++i) {
    s.vertices_m.emplace_back((i & 1) ? h_m.x() : -h_m.x(), (i & 2) ? h_m.y() : -h_m.y(),
                              (i & 4) ? h_m.z() : -h_m.z());
  }
  // -x, +x, -y, +y, -z, +z.
  s.faces = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  for (int k = 0; k < 3; ++k) {
    for (const double sign : {-1.0, 1.0}) {
      s.normals.push_back(sign * Eigen::Vector3d::Unit(k));
      s.offsets_m.push_back(h_m[k]);
    }
  }
  s.volume_m3 = 8.0 * h_m.prod();
  const Eigen::Vector3d sq = h_m.cwiseAbs2();
  s.inertia_per_kg_m2 =
      Eigen::Vector3d(sq.y() + sq.z(), sq.x() + sq.z(), sq.x() + sq.y()).asDiagonal() * (1.0 / 3.0);
  s.radius_m = h_m.norm();
  s.half_extents_m = h_m;
  return s;
}

// A prism of thickness t_m along body z over the triangle p0, p1, p2 (body x, y; counter-clockwise
// seen from +z; its centroid must be the origin, so the prism's centre of mass is too). Vertices
// 0-2 are the triangle at z = +t/2 (the face toward +z), 3-5 the same at z = -t/2. Its inertia is
// not needed by the tests that use it and left zero.
inline ConvexShape triangular_slab(const std::array<Eigen::Vector2d, 3>& p, double t_m) {
  ConvexShape s;
  const double hz = 0.5 * t_m;
  for (const double z : {hz, -hz}) {
    for (const Eigen::Vector2d& q : p) s.vertices_m.emplace_back(q.x(), q.y(), z);
  }
  s.faces = {{0, 1, 2}, {3, 5, 4}};
  s.normals = {Eigen::Vector3d::UnitZ(), -Eigen::Vector3d::UnitZ()};
  s.offsets_m = {hz, hz};
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    // Edge i -> j runs counter-clockwise, so the outside is on its right: normal (dy, -dx).
    const Eigen::Vector2d d = p[static_cast<std::size_t>(j)] - p[static_cast<std::size_t>(i)];
    const Eigen::Vector3d n = Eigen::Vector3d(d.y(), -d.x(), 0.0).normalized();
    s.faces.push_back({i, i + 3, j + 3, j});
    s.normals.push_back(n);
    s.offsets_m.push_back(n.dot(s.vertices_m[static_cast<std::size_t>(i)]));
  }
  const Eigen::Vector2d e1 = p[1] - p[0];
  const Eigen::Vector2d e2 = p[2] - p[0];
  s.volume_m3 = 0.5 * (e1.x() * e2.y() - e1.y() * e2.x()) * t_m;
  for (const Eigen::Vector3d& v : s.vertices_m) {
    s.radius_m = std::max(s.radius_m, v.norm());
    s.half_extents_m = s.half_extents_m.cwiseMax(v.cwiseAbs());
  }
  return s;
}

// A fragment that is `shape` (kept alive by the caller) at centre_m with body axes `rotation`.
inline FragmentState shaped_fragment(
    const ConvexShape& shape, const Eigen::Vector3d& centre_m,
    const Eigen::Matrix3d& rotation = Eigen::Matrix3d::Identity()) {
  FragmentState f;
  f.position_m = centre_m;
  f.rotation = rotation;
  f.half_extents_m = shape.half_extents_m;
  f.shape = &shape;
  f.mass_kg = 1.0;
  f.radius_m = shape.radius_m;
  return f;
}

// The same fragment as the box that holds it (what every test written for boxes saw).
inline FragmentState as_box(FragmentState f) {
  f.shape = nullptr;
  f.radius_m = f.half_extents_m.norm();
  return f;
}

}  // namespace fragsim::test
