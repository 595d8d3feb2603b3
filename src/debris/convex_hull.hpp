#pragma once
// A convex piece from a cloud of points, made of the hull (Qhull), then the volume, centre of mass
// and inertia of the solid hull of uniform density, in the shape's body frame.

#include <Eigen/Core>
#include <memory>
#include <stdexcept>
#include <vector>

#include "control/geometry/convex_shape.hpp"

namespace fragsim {

// Points whose hull has no volume (fewer than four, all on a plane or a line, or a hull smaller
// than kMinHullVolume_m3), or a non-finite point. The message says which, without a file name:
// the caller knows what the points are.
class DegenerateHull : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Smaller than a 0.1 mm cube, below what ODE can step as a body, and the size at which Qhull's
// rounding of a flat cloud would otherwise pass for a piece.
constexpr double kMinHullVolume_m3 = 1e-12;

// The most vertices a piece's hull keeps. It is PhysX's limit for a convex mesh (Unreal and Unity
// use PhysX), so a collision hull a game engine accepts is taken as it is. ODE's set-up of a convex
// geom is quadratic in its size (a 40,000-triangle hull takes 9.9 s); a hull of 255 vertices has at
// most 506 triangles. A larger hull is simplified (see convex_hull), which for N evenly spread
// points on a sphere loses about sqrt(3) pi / N of the volume, 2.1% at 255.
constexpr int kMaxHullVertices = 255;

struct HullPiece {
  std::shared_ptr<const ConvexShape> shape;
  Eigen::Vector3d centre_m;  // the centre of mass in the points' frame
  // When the points' hull had more than kMaxHullVertices vertices, how many, and its volume (the
  // shape is the simplified hull). 0 when the hull is the points' own.
  int full_vertices = 0;
  double full_volume_m3 = 0.0;
};

// The hull of `points_m`, its faces merged where coplanar, with the vertices being input points
// exactly (moved to the centre of mass). A hull of more than kMaxHullVertices vertices is replaced
// by the hull of a subset of them, the support points (the vertex farthest along a direction) of
// kMaxHullVertices directions spread evenly over the sphere (a Fibonacci lattice), topped up by the
// vertex farthest from those chosen while fewer. It is deterministic, inside the full hull, and has
// its own volume, centre of mass and inertia. Throws DegenerateHull.
HullPiece convex_hull(const std::vector<Eigen::Vector3d>& points_m);

// The solid's volume, centre of mass and second moments from its faces (counter-clockwise from
// outside), by tetrahedra from a point inside (Tonon 2004, "Explicit exact formulas for the 3-D
// tetrahedron inertia tensor in terms of its vertex coordinates").
struct MassProperties {
  double volume_m3 = 0.0;
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();
  Eigen::Matrix3d inertia_per_kg_m2 = Eigen::Matrix3d::Zero();  // about centre_m
};
MassProperties polyhedron_mass(const std::vector<Eigen::Vector3d>& vertices_m,
                               const std::vector<std::vector<int>>& faces);

// The shape of the polyhedron (vertices and counter-clockwise faces) in the frame of its centre of
// mass, every field of ConvexShape filled; the centre in the vertices' frame through `centre_m`.
std::shared_ptr<ConvexShape> shape_of_polyhedron(const std::vector<Eigen::Vector3d>& vertices_m,
                                                 const std::vector<std::vector<int>>& faces,
                                                 Eigen::Vector3d* centre_m);

// The same shape scaled by `s` about its centre of mass (the gap between pieces).
std::shared_ptr<ConvexShape> scaled_shape(const ConvexShape& shape, double s);

}  // namespace fragsim
