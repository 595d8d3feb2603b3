// The swept near-plane test on hand-placed boxes: a camera at the origin looking down -z with the
// default frustum (near 0.1 m, half width 0.10264 m, half height 0.05774 m).

#include "metrics/near_plane_metric.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <iostream>
#include <random>

#include "support/convex_shapes.hpp"
#include "support/test_scenes.hpp"

namespace fragsim {
namespace {

FragmentState box_at(const Eigen::Vector3d& p, double half_m = 0.01) {
  return test::box_at(p, half_m);
}

// Runs the metric over a path of positions (one snapshot each) and returns its summary.
RunSummary sweep(const std::vector<Eigen::Vector3d>& path, double half_m = 0.01) {
  NearPlaneMetric metric;
  CameraPose cam;
  std::vector<FragmentState> frag{box_at(path[0], half_m)};
  StepSnapshot snap;
  snap.camera = cam;
  snap.camera_body_half_m = Eigen::Vector3d::Constant(0.001);
  snap.fragments = frag;
  metric.begin({nullptr, "test", 1, static_cast<int>(path.size()) - 1, 1.0 / 60.0}, snap);
  for (std::size_t k = 1; k < path.size(); ++k) {
    frag[0] = box_at(path[k], half_m);
    snap.step = static_cast<int>(k);
    metric.observe(snap);
  }
  RunSummary s;
  metric.fill(s);
  return s;
}

TEST(NearPlaneMetric, CentreSweepingThroughTheRectangleCountsOnce) {
  // From 0.25 m in front to 0.05 m behind the eye in one step: never sampled at the near plane.
  const RunSummary s = sweep({{0.0, 0.0, -0.25}, {0.0, 0.0, 0.05}, {0.0, 0.0, 0.35}});
  EXPECT_EQ(s.intersections.near_fragments, 1);
  EXPECT_EQ(s.intersections.near_fragment_steps, 1);
}

TEST(NearPlaneMetric, PassingOneCentimetreOutsideDoesNotCount) {
  // The box's edge passes 1 cm beyond the rectangle's right edge: x = 0.10264 + 0.01 + 0.01.
  const double x = 0.1 * std::tan(30.0 * kPi / 180.0) * 16.0 / 9.0 + 0.02;
  EXPECT_EQ(sweep({{x, 0.0, -0.25}, {x, 0.0, 0.05}}).intersections.near_fragments, 0);
  // And 1 cm above the top edge.
  const double y = 0.1 * std::tan(30.0 * kPi / 180.0) + 0.02;
  EXPECT_EQ(sweep({{0.0, y, -0.25}, {0.0, y, 0.05}}).intersections.near_fragments, 0);
  // Just inside (1 mm overlap) it counts.
  EXPECT_EQ(sweep({{x - 0.011, 0.0, -0.25}, {x - 0.011, 0.0, 0.05}}).intersections.near_fragments,
            1);
}

TEST(NearPlaneMetric, StoppingShortOfThePlaneDoesNotCount) {
  // The box's near face stops 1 cm before the plane: centre at depth 0.1 + 0.01 + 0.01.
  EXPECT_EQ(sweep({{0.0, 0.0, -0.5}, {0.0, 0.0, -0.12}}).intersections.near_fragments, 0);
  EXPECT_EQ(sweep({{0.0, 0.0, -0.5}, {0.0, 0.0, -0.105}}).intersections.near_fragments, 1);
}

TEST(NearPlaneMetric, DiagonalSweepAcrossTheCornerRegion) {
  // Enters the plane's depth only where it is already 5 cm beyond the side: no intersection,
  // although both end points' x and depth ranges, taken apart, overlap the rectangle's.
  EXPECT_EQ(sweep({{0.0, 0.0, -0.3}, {0.3, 0.0, 0.1}}).intersections.near_fragments, 0);
}

// ---- Convex pieces (FragmentState::shape), counted by the exact polytope test (HullSweep): the
// tetrahedron of circumradius R = 6 cm
// (test::regular_tetrahedron(R / sqrt(3))), its vertex 0 along body (1, 1, 1), the faces R / 3 =
// 2 cm from its centre; its body box reaches R = 6 cm along any axis that (1, 1, 1) is turned to.

struct Swept {
  RunSummary summary;
  std::vector<int> per_step;
};

// Runs the metric over one fragment moved along `path` (one snapshot per point).
Swept sweep_piece(const FragmentState& piece, const std::vector<Eigen::Vector3d>& path) {
  NearPlaneMetric metric;
  std::vector<FragmentState> frag{piece};
  frag[0].position_m = path[0];
  StepSnapshot snap;
  snap.camera_body_half_m = Eigen::Vector3d::Constant(0.001);
  snap.fragments = frag;
  metric.begin({nullptr, "test", 1, static_cast<int>(path.size()) - 1, 1.0 / 60.0}, snap);
  for (std::size_t k = 1; k < path.size(); ++k) {
    frag[0].position_m = path[k];
    snap.step = static_cast<int>(k);
    metric.observe(snap);
  }
  Swept out;
  metric.fill(out.summary);
  out.per_step = metric.per_step();
  return out;
}

Eigen::Matrix3d turn_vertex_to(const Eigen::Vector3d& dir) {
  return Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::Ones(), dir).toRotationMatrix();
}

constexpr double kTetraRadiusM = 0.06;

// Fired straight at the lens along the view axis at 6 m/s, 60 Hz: 0.1 m a step, the centre's depth
// 2.05 - 0.1 k after step k.
std::vector<Eigen::Vector3d> straight_at_lens() {
  std::vector<Eigen::Vector3d> path;
  for (int k = 0; k <= 25; ++k) path.emplace_back(0.0, 0.0, -(2.05 - 0.1 * k));
  return path;
}

TEST(NearPlaneMetric, TetrahedronVertexFirstAtTheLens) {
  const ConvexShape t = test::regular_tetrahedron(kTetraRadiusM / std::sqrt(3.0));
  // Vertex 0 toward the camera (world +z): nearest depth c - 0.06, farthest c + 0.02. It spans the
  // near plane (0.1 m) while the centre is in [0.08, 0.16]: step 19 (0.25 -> 0.15, the vertex
  // crosses at s = 0.9) and step 20 (0.15 -> 0.05, until the far face passes at s = 0.7).
  const Swept hull = sweep_piece(
      test::shaped_fragment(t, Eigen::Vector3d::Zero(), turn_vertex_to(Eigen::Vector3d::UnitZ())),
      straight_at_lens());
  EXPECT_EQ(hull.summary.intersections.near_fragments, 1);
  EXPECT_EQ(hull.summary.intersections.near_fragment_steps, 2);
  EXPECT_EQ(hull.per_step[18], 1);  // step 19
  EXPECT_EQ(hull.per_step[19], 1);  // step 20
}

TEST(NearPlaneMetric, TetrahedronFaceFirstAtTheLensAgainstItsBox) {
  const ConvexShape t = test::regular_tetrahedron(kTetraRadiusM / std::sqrt(3.0));
  // Face first (vertex 0 away from the camera): nearest depth c - 0.02 (the face's three
  // vertices), farthest c + 0.06; it spans the plane for c in [0.04, 0.12]: steps 20 (the face
  // crosses at s = 0.3) and 21 (0.05 -> -0.05, the vertex passes at s = 0.1). Its body box reaches
  // 0.06 both ways, c in [0.04, 0.16]: steps 19 to 21, one step too early.
  const FragmentState f =
      test::shaped_fragment(t, Eigen::Vector3d::Zero(), turn_vertex_to(-Eigen::Vector3d::UnitZ()));
  const Swept hull = sweep_piece(f, straight_at_lens());
  const Swept box = sweep_piece(test::as_box(f), straight_at_lens());
  EXPECT_EQ(hull.summary.intersections.near_fragment_steps, 2);
  EXPECT_EQ(hull.per_step[18], 0);
  EXPECT_EQ(hull.per_step[19], 1);
  EXPECT_EQ(hull.per_step[20], 1);
  EXPECT_EQ(box.summary.intersections.near_fragment_steps, 3);
  EXPECT_EQ(box.per_step[18], 1);
}

TEST(NearPlaneMetric, TetrahedronBesideTheLensMissesWhereItsBoxWouldCount) {
  const ConvexShape t = test::regular_tetrahedron(kTetraRadiusM / std::sqrt(3.0));
  // Right of the lens with vertex 0 pointing away (+x): its nearest vertices (the face across
  // from vertex 0) lie R / 3 left of its centre. Centre at x = w + 0.01 + R / 3, w the near half
  // width: those vertices miss the rectangle's edge by 1 cm, while the body box reaches R = 6 cm
  // left of the centre, 3 cm into the rectangle.
  const double w = 0.1 * std::tan(30.0 * kPi / 180.0) * 16.0 / 9.0;
  const double x = w + 0.01 + kTetraRadiusM / 3.0;
  const FragmentState f =
      test::shaped_fragment(t, Eigen::Vector3d::Zero(), turn_vertex_to(Eigen::Vector3d::UnitX()));
  const std::vector<Eigen::Vector3d> path{{x, 0.0, -0.25}, {x, 0.0, 0.05}};
  EXPECT_EQ(sweep_piece(f, path).summary.intersections.near_fragments, 0);
  EXPECT_EQ(sweep_piece(test::as_box(f), path).summary.intersections.near_fragments, 1);
  // 1 mm closer than touching, it counts.
  const std::vector<Eigen::Vector3d> inside{{x - 0.011, 0.0, -0.25}, {x - 0.011, 0.0, 0.05}};
  EXPECT_EQ(sweep_piece(f, inside).summary.intersections.near_fragments, 1);
}

TEST(NearPlaneMetric, SlabPastTheCornerIsNotCountedThoughItsCameraBoxWouldBe) {
  // A 1 cm slab facing the camera, the triangle A = (w - 0.01, h + 0.05), B = (w + 0.05, h - 0.01),
  // C = (w + 0.08, h + 0.08) in camera x, y (w, h the near half sizes), flown through the near
  // plane. Its edge AB lies on x + y = w + h + 0.04, 4 / sqrt(2) = 2.8 cm beyond the rectangle's
  // corner (w, h), and the triangle lies beyond that edge: no contact. Its camera-aligned box,
  // [w - 0.01, w + 0.08] x [h - 0.01, h + 0.08], overlaps the rectangle by 1 cm each way.
  const double w = 0.1 * std::tan(30.0 * kPi / 180.0) * 16.0 / 9.0;
  const double h = 0.1 * std::tan(30.0 * kPi / 180.0);
  const Eigen::Vector2d pa(w - 0.01, h + 0.05);
  const Eigen::Vector2d pb(w + 0.05, h - 0.01);
  const Eigen::Vector2d pc(w + 0.08, h + 0.08);
  const Eigen::Vector2d g = (pa + pb + pc) / 3.0;
  const ConvexShape slab = test::triangular_slab({pa - g, pb - g, pc - g}, 0.01);
  const FragmentState f = test::shaped_fragment(slab, Eigen::Vector3d::Zero());
  const std::vector<Eigen::Vector3d> path{{g.x(), g.y(), -0.3}, {g.x(), g.y(), 0.1}};
  EXPECT_EQ(sweep_piece(f, path).summary.intersections.near_fragments, 0);
  EXPECT_EQ(sweep_piece(test::as_box(f), path).summary.intersections.near_fragments, 1);
  FragmentState at_a = f;
  at_a.position_m = path[0];
  FragmentState at_b = f;
  at_b.position_m = path[1];
  EXPECT_TRUE(
      sweep_meets_near_rectangle(sweep_end(CameraPose{}, at_a), sweep_end(CameraPose{}, at_b)));
  // Moved 3 cm toward the centre along (-1, -1), it meets the corner.
  const Eigen::Vector3d in(-0.03, -0.03, 0.0);
  EXPECT_EQ(sweep_piece(f, {path[0] + in, path[1] + in}).summary.intersections.near_fragments, 1);
}

TEST(NearPlaneMetric, CubeHullCountsAsItsBox) {
  // A box's test bounds it by its camera-aligned extents, exact when its axes are the camera's
  // (up to order and sign); the hull test is exact for the polytope. So a box hull turned by one
  // of the 24 rotations that map axes to axes counts the very steps its box counts, on random
  // paths through the lens's neighbourhood (tolerance: none; a path would have to pass within
  // ~1e-16 m of a boundary to tell them apart). Turned at random, the hull counts a subset of its
  // box's steps: the box test's own over-count for turned boxes, printed.
  const ConvexShape cube = test::box_hull({0.02, 0.03, 0.05});
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Eigen::Matrix3d> axis_turns;
  const int perms[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  for (const auto& p : perms) {
    for (int signs = 0; signs < 8; ++signs) {
      Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
      for (int k = 0; k < 3; ++k) m(p[k], k) = (signs >> k) & 1 ? -1.0 : 1.0;
      if (m.determinant() > 0.0) axis_turns.push_back(m);
    }
  }
  ASSERT_EQ(axis_turns.size(), 24u);
  int hits = 0;
  int box_steps = 0;
  int hull_steps = 0;
  for (int trial = 0; trial < 1000; ++trial) {
    const bool aligned = trial % 2 == 0;
    const Eigen::Matrix3d rot =
        aligned
            ? axis_turns[static_cast<std::size_t>(trial / 2 % 24)]
            : Eigen::Quaterniond(u(rng), u(rng), u(rng), u(rng)).normalized().toRotationMatrix();
    const FragmentState f = test::shaped_fragment(cube, Eigen::Vector3d::Zero(), rot);
    std::vector<Eigen::Vector3d> path;
    Eigen::Vector3d p(0.3 * u(rng), 0.2 * u(rng), -0.6);
    const Eigen::Vector3d v(0.05 * u(rng), 0.05 * u(rng), 0.1);
    for (int k = 0; k <= 8; ++k) path.push_back(p + k * v);
    const Swept hull = sweep_piece(f, path);
    const Swept box = sweep_piece(test::as_box(f), path);
    if (aligned) {
      EXPECT_EQ(hull.per_step, box.per_step) << "trial " << trial;
      hits += hull.summary.intersections.near_fragments;
    } else {
      for (std::size_t k = 0; k < hull.per_step.size(); ++k) {
        EXPECT_LE(hull.per_step[k], box.per_step[k]) << "trial " << trial;
      }
      box_steps += box.summary.intersections.near_fragment_steps;
      hull_steps += hull.summary.intersections.near_fragment_steps;
    }
    EXPECT_EQ(hull.summary.intersections.camera_hit_fragments,
              box.summary.intersections.camera_hit_fragments);
  }
  EXPECT_GT(hits, 50);  // the paths do reach the rectangle, so the comparison means something
  std::cout << "[ measure  ] 500 turned boxes: near steps " << box_steps << " as boxes, "
            << hull_steps << " as hulls\n";
  EXPECT_LE(hull_steps, box_steps);
}

}  // namespace
}  // namespace fragsim
