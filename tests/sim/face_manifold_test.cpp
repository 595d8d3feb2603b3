// The face manifold of two convex hulls (face_manifold.hpp): a piece resting face on face gets
// the corners of the overlap, as deep as they lie below the reference face; an edge or corner
// contact gets none (the world keeps the collider's one point then).

#include "sim/face_manifold.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

namespace fragsim {
namespace {

const Eigen::Matrix3d kUpright = Eigen::Matrix3d::Identity();
const Eigen::Vector3d kUp = Eigen::Vector3d::UnitY();
// A slab 2 m x 1 m x 2 m centred on the origin: its top face at y = 0.5.
const Eigen::Vector3d kSlabHalf_m(1.0, 0.5, 1.0);
constexpr double kCubeHalf_m = 0.1;
constexpr double kSunk_m = 0.001;

// A 0.2 m cube whose bottom face is sunk kSunk_m into the slab's top, centred at (x, z).
WorldHull cube_on_slab(double x_m, double z_m, const Eigen::Matrix3d& rotation = kUpright) {
  const Eigen::Vector3d centre_m(x_m, 0.5 + kCubeHalf_m - kSunk_m, z_m);
  return place_box(centre_m, rotation, Eigen::Vector3d::Constant(kCubeHalf_m));
}

WorldHull slab() {
  return place_box(Eigen::Vector3d::Zero(), kUpright, kSlabHalf_m);
}

TEST(FaceManifold, PlacedBoxHasItsCornersAndFacesInTheWorld) {
  const Eigen::Matrix3d quarter_turn =
      Eigen::AngleAxisd(0.5 * M_PI, Eigen::Vector3d::UnitY()).toRotationMatrix();
  const Eigen::Vector3d centre_m(1.0, 2.0, 3.0);
  const Eigen::Vector3d half_m(0.1, 0.2, 0.3);
  const WorldHull h = place_box(centre_m, quarter_turn, half_m);
  ASSERT_EQ(h.vertices_m.size(), 8u);
  ASSERT_EQ(h.normals.size(), 6u);
  for (std::size_t i = 0; i < 8; ++i) {
    const Eigen::Vector3d corner((i & 1) ? 0.1 : -0.1, (i & 2) ? 0.2 : -0.2, (i & 4) ? 0.3 : -0.3);
    EXPECT_LT((h.vertices_m[i] - (centre_m + quarter_turn * corner)).norm(), 1e-12);
  }
  // Every corner lies on or behind every face's plane, and each face's own corners on it.
  for (std::size_t f = 0; f < 6; ++f) {
    for (const Eigen::Vector3d& v : h.vertices_m) {
      EXPECT_LE(h.normals[f].dot(v), h.offsets_m[f] + 1e-12);
    }
    for (const int v : (*h.faces)[f]) {
      EXPECT_NEAR(h.normals[f].dot(h.vertices_m[static_cast<std::size_t>(v)]), h.offsets_m[f],
                  1e-12);
    }
  }
}

TEST(FaceManifold, CubeRestingOnASlabGetsItsFourBottomCorners) {
  const FaceManifold m = face_manifold(cube_on_slab(0.0, 0.0), slab(), kUp);
  ASSERT_EQ(m.points.size(), 4u);
  EXPECT_EQ(m.normal, kUp);
  for (const ManifoldPoint& p : m.points) {
    EXPECT_NEAR(p.depth_m, kSunk_m, 1e-12);
    EXPECT_NEAR(std::abs(p.position_m.x()), kCubeHalf_m, 1e-12);
    EXPECT_NEAR(std::abs(p.position_m.z()), kCubeHalf_m, 1e-12);
    EXPECT_NEAR(p.position_m.y(), 0.5 - kSunk_m, 1e-12);
  }
}

TEST(FaceManifold, ACubeOverTheEdgeIsClippedToTheFace) {
  // Half of the cube over the slab's +x side: its corners there are cut back to x = 1.
  const FaceManifold m = face_manifold(cube_on_slab(1.0, 0.0), slab(), kUp);
  ASSERT_EQ(m.points.size(), 4u);
  for (const ManifoldPoint& p : m.points) {
    EXPECT_GE(p.position_m.x(), 0.9 - 1e-12);
    EXPECT_LE(p.position_m.x(), 1.0 + 1e-12);
    EXPECT_NEAR(p.depth_m, kSunk_m, 1e-12);
  }
  const auto at_edge = std::count_if(m.points.begin(), m.points.end(), [](const ManifoldPoint& p) {
    return std::abs(p.position_m.x() - 1.0) < 1e-12;
  });
  EXPECT_EQ(at_edge, 2);
}

TEST(FaceManifold, PointsComeDeepestFirst) {
  // Tilted about z so that its -x bottom edge lies deeper than its +x one.
  const Eigen::Matrix3d tilt = Eigen::AngleAxisd(0.01, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const FaceManifold m = face_manifold(cube_on_slab(0.0, 0.0, tilt), slab(), kUp);
  ASSERT_FALSE(m.points.empty());
  for (std::size_t i = 1; i < m.points.size(); ++i) {
    EXPECT_GE(m.points[i - 1].depth_m, m.points[i].depth_m);
  }
  EXPECT_LT(m.points.front().position_m.x(), 0.0);
}

TEST(FaceManifold, TheBetterFacingHullIsTheReference) {
  // The slab tilted, the cube upright: the cube's bottom face is the reference, and the normal
  // still points from b (the slab) into a (the cube).
  const Eigen::Matrix3d tilt = Eigen::AngleAxisd(0.2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  const WorldHull tilted_slab = place_box(Eigen::Vector3d::Zero(), tilt, kSlabHalf_m);
  const WorldHull cube =
      place_box(Eigen::Vector3d(0.0, 0.6, 0.0), kUpright, Eigen::Vector3d::Constant(kCubeHalf_m));
  const FaceManifold m = face_manifold(cube, tilted_slab, kUp);
  // The slab's face clipped to the cube's bottom face (y = 0.5): only its raised +x side is above
  // it, the two corners there, each as deep as it rises above that face.
  ASSERT_EQ(m.points.size(), 2u);
  EXPECT_EQ(m.normal, kUp);
  for (const ManifoldPoint& p : m.points) {
    EXPECT_NEAR(p.position_m.x(), kCubeHalf_m, 1e-12);
    EXPECT_NEAR(std::abs(p.position_m.z()), kCubeHalf_m, 1e-12);
    EXPECT_NEAR(p.depth_m, p.position_m.y() - 0.5, 1e-12);
    EXPECT_GT(p.depth_m, 0.0);
  }
}

TEST(FaceManifold, AnEdgeOrCornerContactHasNoPoints) {
  // A normal at equal angles to all three axes faces no face of either box within
  // kFaceContactCos.
  const Eigen::Vector3d diagonal = Eigen::Vector3d(1.0, 1.0, 1.0).normalized();
  EXPECT_TRUE(face_manifold(cube_on_slab(0.0, 0.0), slab(), diagonal).points.empty());
}

TEST(FaceManifold, NothingBelowTheReferenceFaceHasNoPoints) {
  // The cube just above the slab: its clipped face lies above the top face.
  const WorldHull cube = place_box(Eigen::Vector3d(0.0, 0.5 + kCubeHalf_m + 0.01, 0.0), kUpright,
                                   Eigen::Vector3d::Constant(kCubeHalf_m));
  EXPECT_TRUE(face_manifold(cube, slab(), kUp).points.empty());
}

}  // namespace
}  // namespace fragsim
