#pragma once
// Convex pieces for the tests and the physics bench, with every field in closed form: a cube, a
// regular tetrahedron, a corner tetrahedron with three different legs, a box of any half extents
// and a thin triangular slab; a brute-force hull of a few random points whose volume and inertia
// come from integrating its tetrahedra (which also checks the closed forms); and fragments that
// are such a shape, or the box that holds it. Faces are counter-clockwise seen from outside
// (ConvexShape's convention); tests/geometry/convex_shapes_test.cpp checks them against their
// vertices.

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

#include "control/geometry/convex_shape.hpp"
#include "control/geometry/fragment_state.hpp"

namespace fragsim::test {

// Fills normals, offsets, radius and half extents from vertices and faces (counter-clockwise seen
// from outside; the first three vertices of a face must not be collinear).
inline ConvexShape finish_shape(std::vector<Eigen::Vector3d> vertices_m,
                                std::vector<std::vector<int>> faces, double volume_m3,
                                const Eigen::Matrix3d& inertia_per_kg_m2) {
  ConvexShape s;
  s.vertices_m = std::move(vertices_m);
  s.faces = std::move(faces);
  for (const std::vector<int>& f : s.faces) {
    const Eigen::Vector3d& a = s.vertices_m[static_cast<std::size_t>(f[0])];
    const Eigen::Vector3d& b = s.vertices_m[static_cast<std::size_t>(f[1])];
    const Eigen::Vector3d& c = s.vertices_m[static_cast<std::size_t>(f[2])];
    const Eigen::Vector3d n = (b - a).cross(c - a).normalized();
    s.normals.push_back(n);
    s.offsets_m.push_back(n.dot(a));
  }
  s.volume_m3 = volume_m3;
  s.inertia_per_kg_m2 = inertia_per_kg_m2;
  for (const Eigen::Vector3d& v : s.vertices_m) {
    s.radius_m = std::max(s.radius_m, v.norm());
    s.half_extents_m = s.half_extents_m.cwiseMax(v.cwiseAbs());
  }
  return s;
}

// Edge 2 h: volume 8 h^3, inertia (2h)^2 / 6 per kg about every axis.
inline ConvexShape cube_shape(double half_m) {
  std::vector<Eigen::Vector3d> v;
  for (int i = 0; i < 8; ++i) {
    v.emplace_back((i & 1) ? half_m : -half_m, (i & 2) ? half_m : -half_m,
                   (i & 4) ? half_m : -half_m);
  }
  const std::vector<std::vector<int>> faces = {{1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3},
                                               {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1}};
  const double edge_m = 2.0 * half_m;
  return finish_shape(v, faces, edge_m * edge_m * edge_m,
                      Eigen::Matrix3d::Identity() * edge_m * edge_m / 6.0);
}

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

// The corner O, O + a x, O + b y, O + c z, moved so that its centroid (a, b, c) / 4 from the
// corner is the origin. Volume abc / 6. About the corner, per kg, E[x^2] = a^2 / 10 and
// E[xy] = ab / 20; about the centroid, E[x^2] = a^2 (1/10 - 1/16) = 3 a^2 / 80 and
// E[xy] = ab (1/20 - 1/16) = -ab / 80; the inertia tensor is tr(E) 1 - E: I_xx = 3 (b^2 + c^2) / 80
// and I_xy = ab / 80 per kg.
inline ConvexShape corner_tetrahedron(double a_m, double b_m, double c_m) {
  const Eigen::Vector3d centroid(a_m / 4.0, b_m / 4.0, c_m / 4.0);
  const std::vector<Eigen::Vector3d> v = {-centroid, Eigen::Vector3d(a_m, 0, 0) - centroid,
                                          Eigen::Vector3d(0, b_m, 0) - centroid,
                                          Eigen::Vector3d(0, 0, c_m) - centroid};
  const std::vector<std::vector<int>> faces = {{0, 3, 2}, {0, 1, 3}, {0, 2, 1}, {1, 2, 3}};
  Eigen::Matrix3d inertia;
  inertia << 3.0 * (b_m * b_m + c_m * c_m), a_m * b_m, a_m * c_m,  //
      a_m * b_m, 3.0 * (a_m * a_m + c_m * c_m), b_m * c_m,         //
      a_m * c_m, b_m * c_m, 3.0 * (a_m * a_m + b_m * b_m);
  return finish_shape(v, faces, a_m * b_m * c_m / 6.0, inertia / 80.0);
}

// Volume, centroid and covariance E[x x^T] (per unit volume, about the origin) of a closed
// triangulated surface, summed over the tetrahedra it makes with the origin: a tetrahedron of
// vertices p_k has volume det / 6 and integral of x x^T = V / 20 (sum p_k p_k^T + P P^T), P the
// sum of its vertices.
struct MassProperties {
  double volume_m3 = 0.0;
  Eigen::Vector3d centroid_m = Eigen::Vector3d::Zero();
  Eigen::Matrix3d inertia_per_kg_m2 = Eigen::Matrix3d::Zero();  // about the centroid
};

inline MassProperties mass_properties(const std::vector<Eigen::Vector3d>& vertices_m,
                                      const std::vector<std::vector<int>>& faces) {
  double volume = 0.0;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (const std::vector<int>& f : faces) {
    for (std::size_t k = 1; k + 1 < f.size(); ++k) {
      const Eigen::Vector3d& a = vertices_m[static_cast<std::size_t>(f[0])];
      const Eigen::Vector3d& b = vertices_m[static_cast<std::size_t>(f[k])];
      const Eigen::Vector3d& c = vertices_m[static_cast<std::size_t>(f[k + 1])];
      const double v = a.dot(b.cross(c)) / 6.0;
      const Eigen::Vector3d p = a + b + c;  // the origin adds nothing
      volume += v;
      first += v * p / 4.0;
      second += v / 20.0 *
                (a * a.transpose() + b * b.transpose() + c * c.transpose() + p * p.transpose());
    }
  }
  MassProperties m;
  m.volume_m3 = volume;
  m.centroid_m = first / volume;
  const Eigen::Matrix3d covariance =
      second / volume - m.centroid_m * m.centroid_m.transpose();  // about the centroid
  m.inertia_per_kg_m2 = covariance.trace() * Eigen::Matrix3d::Identity() - covariance;
  return m;
}

// The convex hull of a few points in general position (random ones: no four coplanar), by
// brute force: a triple is a face when every other point lies behind its plane. O(n^4), for the
// 8-20 points of a small piece. The result is moved so that its centroid is the origin.
inline ConvexShape simple_hull(std::vector<Eigen::Vector3d> points_m) {
  const int n = static_cast<int>(points_m.size());
  std::vector<std::vector<int>> faces;
  std::vector<char> used(points_m.size(), 0);
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      for (int k = j + 1; k < n; ++k) {
        const Eigen::Vector3d& a = points_m[static_cast<std::size_t>(i)];
        const Eigen::Vector3d normal = (points_m[static_cast<std::size_t>(j)] - a)
                                           .cross(points_m[static_cast<std::size_t>(k)] - a);
        int above = 0;
        int below = 0;
        for (int m = 0; m < n; ++m) {
          if (m == i || m == j || m == k) continue;
          const double side = normal.dot(points_m[static_cast<std::size_t>(m)] - a);
          (side > 0.0 ? above : below) += 1;
        }
        if (above > 0 && below > 0) continue;
        faces.push_back(above == 0 ? std::vector<int>{i, j, k} : std::vector<int>{i, k, j});
        used[static_cast<std::size_t>(i)] = used[static_cast<std::size_t>(j)] =
            used[static_cast<std::size_t>(k)] = 1;
      }
    }
  }
  // Only hull vertices, renumbered.
  std::vector<int> index(points_m.size(), -1);
  std::vector<Eigen::Vector3d> vertices;
  for (std::size_t p = 0; p < points_m.size(); ++p) {
    if (!used[p]) continue;
    index[p] = static_cast<int>(vertices.size());
    vertices.push_back(points_m[p]);
  }
  for (std::vector<int>& f : faces) {
    for (int& v : f) v = index[static_cast<std::size_t>(v)];
  }
  const MassProperties m = mass_properties(vertices, faces);
  if (!(m.volume_m3 > 0.0)) throw std::invalid_argument("simple_hull: degenerate points");
  for (Eigen::Vector3d& v : vertices) v -= m.centroid_m;
  return finish_shape(vertices, faces, m.volume_m3, m.inertia_per_kg_m2);
}

// A random piece of `count` points in a ball of radius `radius_m`, seeded.
inline ConvexShape random_hull(std::mt19937_64& rng, int count, double radius_m) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Eigen::Vector3d> points;
  while (static_cast<int>(points.size()) < count) {
    const Eigen::Vector3d p(u(rng), u(rng), u(rng));
    if (p.squaredNorm() <= 1.0 && p.squaredNorm() >= 0.25) points.push_back(radius_m * p);
  }
  return simple_hull(points);
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
