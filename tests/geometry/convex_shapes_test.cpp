// The hand-built test shapes (tests/support/convex_shapes.hpp) against their own vertices: faces
// counter-clockwise from outside with unit outward normals and the offsets of their planes, every
// vertex inside every plane, and the volume by the divergence theorem. The tests of convex pieces
// rely on these being right.

#include "support/convex_shapes.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace fragsim {
namespace {

void expect_consistent(const ConvexShape& s) {
  ASSERT_EQ(s.faces.size(), s.normals.size());
  ASSERT_EQ(s.faces.size(), s.offsets_m.size());
  double volume = 0.0;
  for (std::size_t i = 0; i < s.faces.size(); ++i) {
    const std::vector<int>& face = s.faces[i];
    ASSERT_GE(face.size(), 3u);
    EXPECT_NEAR(s.normals[i].norm(), 1.0, 1e-15);
    // Newell's normal points outward for a counter-clockwise loop.
    Eigen::Vector3d newell = Eigen::Vector3d::Zero();
    const Eigen::Vector3d& p0 = s.vertices_m[static_cast<std::size_t>(face[0])];
    for (std::size_t k = 0; k < face.size(); ++k) {
      const Eigen::Vector3d& a = s.vertices_m[static_cast<std::size_t>(face[k])];
      const Eigen::Vector3d& b =
          s.vertices_m[static_cast<std::size_t>(face[(k + 1) % face.size()])];
      newell += a.cross(b);
      EXPECT_NEAR(s.normals[i].dot(a), s.offsets_m[i], 1e-15) << "face " << i;
      if (k >= 1 && k + 1 < face.size()) volume += p0.dot(a.cross(b)) / 6.0;
    }
    EXPECT_NEAR(newell.normalized().dot(s.normals[i]), 1.0, 1e-12) << "face " << i;
    for (const Eigen::Vector3d& v : s.vertices_m) {
      EXPECT_LE(s.normals[i].dot(v), s.offsets_m[i] + 1e-15);
    }
  }
  EXPECT_NEAR(volume, s.volume_m3, 1e-15);
  double radius = 0.0;
  Eigen::Vector3d half = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& v : s.vertices_m) {
    radius = std::max(radius, v.norm());
    half = half.cwiseMax(v.cwiseAbs());
  }
  EXPECT_NEAR(radius, s.radius_m, 1e-15);
  EXPECT_TRUE(half.isApprox(s.half_extents_m, 1e-15));
}

TEST(ConvexShapes, RegularTetrahedron) {
  const ConvexShape t = test::regular_tetrahedron(0.5);
  expect_consistent(t);
  // Every edge 2 sqrt(2) a = sqrt(2); the faces R / 3 = sqrt(3) / 6 from the centre.
  for (const auto& face : t.faces) {
    for (std::size_t k = 0; k < 3; ++k) {
      EXPECT_NEAR((t.vertices_m[static_cast<std::size_t>(face[k])] -
                   t.vertices_m[static_cast<std::size_t>(face[(k + 1) % 3])])
                      .norm(),
                  std::sqrt(2.0), 1e-15);
    }
  }
  EXPECT_NEAR(t.offsets_m[0], t.radius_m / 3.0, 1e-15);
}

TEST(ConvexShapes, BoxAndSlab) {
  expect_consistent(test::box_hull({0.125, 0.25, 0.5}));
  expect_consistent(test::box_hull(Eigen::Vector3d::Constant(0.1)));
  const double r = 0.1;  // an equilateral triangle of circumradius r about the origin
  const double c = std::sqrt(3.0) / 2.0;
  expect_consistent(
      test::triangular_slab({{{r, 0.0}, {-0.5 * r, c * r}, {-0.5 * r, -c * r}}}, 0.01));
}

}  // namespace
}  // namespace fragsim
