// The hull and its mass properties against closed forms: a tetrahedron, a cube, a scaled copy.

#include "debris/convex_hull.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <limits>

namespace fragsim {
namespace {

// Every face planar, convex and counter-clockwise seen from outside, with a unit outward normal
// and offset; every vertex inside every face's plane; the centre of mass at the origin.
void expect_valid_shape(const ConvexShape& s) {
  ASSERT_EQ(s.faces.size(), s.normals.size());
  ASSERT_EQ(s.faces.size(), s.offsets_m.size());
  const double tol = 1e-12 * std::max(1.0, s.radius_m);
  for (std::size_t f = 0; f < s.faces.size(); ++f) {
    const auto& loop = s.faces[f];
    const Eigen::Vector3d& n = s.normals[f];
    ASSERT_GE(loop.size(), 3u);
    EXPECT_NEAR(n.norm(), 1.0, 1e-14);
    EXPECT_GT(s.offsets_m[f], 0.0);  // the centre of mass is inside
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Eigen::Vector3d& a = s.vertices_m[loop[i]];
      const Eigen::Vector3d& b = s.vertices_m[loop[(i + 1) % loop.size()]];
      const Eigen::Vector3d& c = s.vertices_m[loop[(i + 2) % loop.size()]];
      EXPECT_NEAR(n.dot(a), s.offsets_m[f], tol);
      EXPECT_GT((b - a).cross(c - b).dot(n), 0.0) << "face " << f << " not CCW from outside";
    }
    for (const auto& v : s.vertices_m) EXPECT_LE(n.dot(v), s.offsets_m[f] + tol);
  }
  for (const auto& v : s.vertices_m) {
    EXPECT_LE(v.norm(), s.radius_m);
    EXPECT_TRUE((v.cwiseAbs().array() <= s.half_extents_m.array()).all());
  }
}

TEST(ConvexHull, TetrahedronMatchesTheClosedForm) {
  // The corner tetrahedron of edges a, b, c: volume abc/6, centroid (a, b, c)/4, and (Tonon's
  // formulas) about its centroid Ixx = (b^2 + c^2) 3/80 per kg; the integral of xy is -ab/80 per
  // kg there, so the tensor's entry Ixy = -integral of xy is +ab/80.
  const double a = 2.0;
  const double b = 3.0;
  const double c = 4.0;
  const HullPiece h = convex_hull({{0, 0, 0}, {a, 0, 0}, {0, b, 0}, {0, 0, c}});
  EXPECT_NEAR(h.shape->volume_m3, a * b * c / 6.0, 1e-14);
  EXPECT_NEAR((h.centre_m - Eigen::Vector3d(a, b, c) / 4.0).norm(), 0.0, 1e-15);
  Eigen::Matrix3d expected;
  expected << 3.0 / 80 * (b * b + c * c), a * b / 80, a * c / 80,  //
      a * b / 80, 3.0 / 80 * (a * a + c * c), b * c / 80,          //
      a * c / 80, b * c / 80, 3.0 / 80 * (a * a + b * b);
  EXPECT_NEAR((h.shape->inertia_per_kg_m2 - expected).norm(), 0.0, 1e-14);
  EXPECT_EQ(h.shape->faces.size(), 4u);
  expect_valid_shape(*h.shape);
}

TEST(ConvexHull, CubeWithInnerPointsHasSixSquareFaces) {
  std::vector<Eigen::Vector3d> pts;
  for (int c = 0; c < 8; ++c) pts.emplace_back(c & 1 ? 3.5 : 2.5, c & 2 ? 1.5 : 0.5, c & 4 ? 1 : 0);
  pts.emplace_back(3.0, 1.0, 0.5);  // inside: not a vertex
  pts.emplace_back(3.0, 1.0, 0.0);  // on a face: not a vertex either
  const HullPiece h = convex_hull(pts);
  EXPECT_EQ(h.shape->vertices_m.size(), 8u);
  ASSERT_EQ(h.shape->faces.size(), 6u);
  for (const auto& f : h.shape->faces) EXPECT_EQ(f.size(), 4u);
  EXPECT_NEAR(h.shape->volume_m3, 1.0, 1e-14);
  EXPECT_NEAR((h.centre_m - Eigen::Vector3d(3.0, 1.0, 0.5)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((h.shape->inertia_per_kg_m2 - Eigen::Matrix3d::Identity() / 6.0).norm(), 0.0, 1e-15);
  EXPECT_NEAR(h.shape->radius_m, std::sqrt(0.75), 1e-15);
  EXPECT_NEAR((h.shape->half_extents_m - Eigen::Vector3d::Constant(0.5)).norm(), 0.0, 1e-15);
  expect_valid_shape(*h.shape);
}

TEST(ConvexHull, ScaledShapeScalesEveryField) {
  const HullPiece h = convex_hull({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}});
  const auto s = scaled_shape(*h.shape, 0.5);
  EXPECT_NEAR(s->volume_m3, h.shape->volume_m3 / 8.0, 1e-16);
  EXPECT_NEAR((s->inertia_per_kg_m2 - h.shape->inertia_per_kg_m2 / 4.0).norm(), 0.0, 1e-16);
  EXPECT_NEAR(s->radius_m, h.shape->radius_m / 2.0, 1e-16);
  expect_valid_shape(*s);
}

TEST(ConvexHull, DegenerateCloudsAreRefused) {
  EXPECT_THROW(convex_hull({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}), DegenerateHull);
  EXPECT_THROW(convex_hull({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {0.5, 0.2, 0}}),
               DegenerateHull);  // coplanar
  EXPECT_THROW(convex_hull({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}}), DegenerateHull);
  // A tetrahedron of 1e-13 m^3: a hull, but no piece.
  EXPECT_THROW(convex_hull({{0, 0, 0}, {1e-4, 0, 0}, {0, 1e-4, 0}, {0, 0, 6e-5}}), DegenerateHull);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(convex_hull({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, nan}}), DegenerateHull);
}

}  // namespace
}  // namespace fragsim
