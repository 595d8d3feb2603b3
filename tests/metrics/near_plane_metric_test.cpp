// The swept near-plane test on hand-placed boxes: a camera at the origin looking down -z with the
// default frustum (near 0.1 m, half width 0.10264 m, half height 0.05774 m).

#include "metrics/near_plane_metric.hpp"

#include <gtest/gtest.h>

namespace fragsim {
namespace {

FragmentState box_at(const Eigen::Vector3d& p, double half_m = 0.01) {
  FragmentState f;
  f.position_m = p;
  f.half_extents_m = Eigen::Vector3d::Constant(half_m);
  f.mass_kg = 1.0;
  f.radius_m = half_m * std::sqrt(3.0);
  return f;
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
  EXPECT_EQ(s.near_fragments, 1);
  EXPECT_EQ(s.near_fragment_steps, 1);
}

TEST(NearPlaneMetric, PassingOneCentimetreOutsideDoesNotCount) {
  // The box's edge passes 1 cm beyond the rectangle's right edge: x = 0.10264 + 0.01 + 0.01.
  const double x = 0.1 * std::tan(30.0 * kPi / 180.0) * 16.0 / 9.0 + 0.02;
  EXPECT_EQ(sweep({{x, 0.0, -0.25}, {x, 0.0, 0.05}}).near_fragments, 0);
  // And 1 cm above the top edge.
  const double y = 0.1 * std::tan(30.0 * kPi / 180.0) + 0.02;
  EXPECT_EQ(sweep({{0.0, y, -0.25}, {0.0, y, 0.05}}).near_fragments, 0);
  // Just inside (1 mm overlap) it counts.
  EXPECT_EQ(sweep({{x - 0.011, 0.0, -0.25}, {x - 0.011, 0.0, 0.05}}).near_fragments, 1);
}

TEST(NearPlaneMetric, StoppingShortOfThePlaneDoesNotCount) {
  // The box's near face stops 1 cm before the plane: centre at depth 0.1 + 0.01 + 0.01.
  EXPECT_EQ(sweep({{0.0, 0.0, -0.5}, {0.0, 0.0, -0.12}}).near_fragments, 0);
  EXPECT_EQ(sweep({{0.0, 0.0, -0.5}, {0.0, 0.0, -0.105}}).near_fragments, 1);
}

TEST(NearPlaneMetric, DiagonalSweepAcrossTheCornerRegion) {
  // Enters the plane's depth only where it is already 5 cm beyond the side: no intersection,
  // although both end points' x and depth ranges, taken apart, overlap the rectangle's.
  EXPECT_EQ(sweep({{0.0, 0.0, -0.3}, {0.3, 0.0, 0.1}}).near_fragments, 0);
}

}  // namespace
}  // namespace fragsim
