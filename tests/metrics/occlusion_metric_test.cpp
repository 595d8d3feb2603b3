// Screen occlusion: hand-worked boxes in front of a 90-degree, square camera at the origin looking
// down -z (so a point at depth z and lateral offset x has NDC x / z), and a brute-force ray test
// as an independent reference for the clipping, projection and inside rule.

#include "metrics/occlusion_metric.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "support/convex_shapes.hpp"
#include "support/test_scenes.hpp"

namespace fragsim {
namespace {

using test::square_camera;

MetricsDef grid(int width_px, double central_share = 0.5) {
  MetricsDef def;
  def.grid_width_px = width_px;
  def.central_share = central_share;
  return def;
}

FragmentState box(const Eigen::Vector3d& centre_m, const Eigen::Vector3d& half_m,
                  const Eigen::Matrix3d& rotation = Eigen::Matrix3d::Identity()) {
  FragmentState f;
  f.position_m = centre_m;
  f.half_extents_m = half_m;
  f.rotation = rotation;
  f.radius_m = half_m.norm();
  return f;
}

StepSnapshot snapshot(int step, const CameraPose& cam, const std::vector<FragmentState>& frags) {
  StepSnapshot s;
  s.step = step;
  s.camera = cam;
  s.fragments = frags;
  return s;
}

RunInfo run_info(int fragments, int steps) {
  RunInfo info;
  info.fragment_count = fragments;
  info.step_count = steps;
  info.dt_s = 1.0 / 60.0;
  return info;
}

struct Shares {
  double viewport = 0.0;
  double central = 0.0;
  double single = 0.0;
};

// One step with these fragments; the initial snapshot is empty so it cannot leak into the step.
Shares measure(const MetricsDef& def, const CameraPose& cam,
               const std::vector<FragmentState>& frags) {
  OcclusionMetric m(def);
  const std::vector<FragmentState> none;
  m.begin(run_info(static_cast<int>(frags.size()), 1), snapshot(0, cam, none));
  m.observe(snapshot(1, cam, frags));
  RunSummary s;
  m.fill(s);
  return {s.occlusion.mean, s.occlusion.central_mean, s.occlusion.single_fragment_max};
}

// A thin plate facing the camera at depth_m: its NDC half size is half_m / depth_m.
FragmentState plate(double x_m, double y_m, double depth_m, double half_x_m, double half_y_m) {
  return box({x_m, y_m, -depth_m}, {half_x_m, half_y_m, 1e-3});
}

TEST(OcclusionMetric, GridFollowsCameraAspectAndCentralRegionIsCentred) {
  OcclusionMetric m(grid(160, 0.5));
  CameraPose cam;  // 16:9
  const std::vector<FragmentState> none;
  m.begin(run_info(0, 0), snapshot(0, cam, none));
  EXPECT_EQ(m.width_px(), 160);
  EXPECT_EQ(m.height_px(), 90);
  EXPECT_EQ(m.central_x0_px(), 40);
  EXPECT_EQ(m.central_x1_px(), 120);
  // 45 rows cannot be centred on 90 in whole pixels: margins of round(22.5) = 23 leave 44.
  EXPECT_EQ(m.central_y0_px(), 23);
  EXPECT_EQ(m.central_y1_px(), 67);

  OcclusionMetric thin(grid(8, 0.01));
  cam.aspect = 100.0;
  thin.begin(run_info(0, 0), snapshot(0, cam, none));
  EXPECT_EQ(thin.height_px(), 1);      // never fewer than one row
  EXPECT_EQ(thin.central_x0_px(), 3);  // a tiny share still keeps a centred pixel pair
  EXPECT_EQ(thin.central_x1_px(), 5);
  EXPECT_EQ(thin.central_y0_px(), 0);
  EXPECT_EQ(thin.central_y1_px(), 1);
}

TEST(OcclusionMetric, FacingPlateCoversItsProjectedSquare) {
  // Half extents 0.5 at depth 2 give an NDC square of side 0.5: a quarter of the viewport's side,
  // share 0.0625, and 0.25 of the central half. The front face is at depth 1.99, so exactly the
  // NDC half size is 0.5 / 1.99 = 0.25126 (share 0.06313), pixel edges 37.44 and 62.56 on the
  // 100-pixel grid: centres 37.5 .. 62.5, 26 x 26 = 676 pixels.
  const Shares s = measure(grid(100, 0.5), square_camera(), {box({0, 0, -2}, {0.5, 0.5, 0.01})});
  const double two_rows = 2.0 * 25.0 / (100.0 * 100.0);  // two pixel rows of the square's side
  EXPECT_NEAR(s.viewport, 0.0625, two_rows + 0.001);     // + the box's thickness
  EXPECT_NEAR(s.viewport, 0.25126 * 0.25126 / 1.0, two_rows);
  EXPECT_NEAR(s.viewport, 676.0 / 10000.0, 0.5 / 10000.0);  // the pixel rule, exactly
  EXPECT_NEAR(s.central, 0.25, 4.0 * two_rows + 0.004);     // the central region is 1/4 as big
  EXPECT_NEAR(s.central, 676.0 / 2500.0, 0.5 / 2500.0);
  EXPECT_NEAR(s.single, s.viewport, 1e-12);
}

TEST(OcclusionMetric, RowsCountDownFromTheTop) {
  OcclusionMetric m(grid(100));
  const CameraPose cam = square_camera();
  // Upper-left quadrant of the screen: NDC x in [-0.75, -0.25], y in [0.25, 0.75].
  const std::vector<FragmentState> frags{plate(-1.0, 1.0, 2.0, 0.5, 0.5)};
  m.begin(run_info(1, 1), snapshot(0, cam, frags));
  m.observe(snapshot(1, cam, frags));
  const auto at = [&](int col, int row) { return m.coverage()[row * m.width_px() + col]; };
  EXPECT_EQ(at(25, 25), 1);  // pixel centre (25.5, 25.5): NDC (-0.49, +0.49)
  EXPECT_EQ(at(25, 74), 0);  // its mirror below the horizon
  EXPECT_EQ(at(74, 25), 0);  // its mirror right of centre
}

TEST(OcclusionMetric, BoxStraddlingNearPlaneCoversOnlyItsClippedPart) {
  // A plate 1 m high tilted 45 degrees about y: in camera coordinates (x, y, depth z) it runs from
  // (-1, ., 0.5) to (1, ., 2.5), i.e. x = z - 1.5. The near plane at 1 m cuts it at x = -0.5, so
  // the visible part projects to the trapezoid with vertical sides at NDC x = -0.5 (y in +-0.5)
  // and x = 1 / 2.5 = 0.4 (y in +-0.2): area 0.9 (1 + 0.4) / 2 = 0.63 of the NDC square's 4.
  // Unclipped, its near end would project to NDC x = -2, y = +-1 and cover far more.
  const double r = 1.0 / std::sqrt(2.0);
  Eigen::Matrix3d rot;  // columns: the long axis, up, and the plate's normal, in world
  rot.col(0) = Eigen::Vector3d(r, 0, -r);  // camera (1, 0, 1) / sqrt 2: farther to the right
  rot.col(1) = Eigen::Vector3d(0, 1, 0);
  rot.col(2) = rot.col(0).cross(rot.col(1));
  const FragmentState tilted = box({0, 0, -1.5}, {std::sqrt(2.0), 0.5, 1e-4}, rot);
  const Shares s = measure(grid(100), square_camera(1.0), {tilted});
  // Half a pixel along the trapezoid's boundary (50 + 20 + 2 x 47.4 = 165 pixels).
  const double half_pixel_band = 0.5 * 165.0 / 10000.0;
  EXPECT_NEAR(s.viewport, 0.63 / 4.0, half_pixel_band);
}

TEST(OcclusionMetric, BoxCutByNearPlaneAcrossItsDepth) {
  // An axis-aligned box from depth 0.5 to 2.5 and x from 0 to 1, y in +-0.5, near plane at 1:
  // the clipped part's widest cross-section is at the near plane, NDC x in [0, 1], y in +-0.5,
  // share 1 x 1 / 4; its pixel edges fall on pixel boundaries (columns 50..99, rows 25..74).
  const Shares s = measure(grid(100), square_camera(1.0), {box({0.5, 0, -1.5}, {0.5, 0.5, 1.0})});
  EXPECT_NEAR(s.viewport, 0.25, 0.5 / 10000.0);
}

TEST(OcclusionMetric, InvisibleBoxesCoverNothing) {
  const CameraPose cam = square_camera(1.0);
  EXPECT_DOUBLE_EQ(measure(grid(100), cam, {box({0, 0, 3}, {0.5, 0.5, 0.5})}).viewport,
                   0.0);  // behind
  // In front of the eye but wholly inside the near distance (unclipped it would fill the view).
  EXPECT_DOUBLE_EQ(measure(grid(100), cam, {box({0, 0, -0.5}, {0.4, 0.4, 0.4})}).viewport, 0.0);
  // Wholly outside each side plane (at depth 2 the view spans +-2).
  for (const Eigen::Vector3d& c : {Eigen::Vector3d(4, 0, -2), Eigen::Vector3d(-4, 0, -2),
                                   Eigen::Vector3d(0, 4, -2), Eigen::Vector3d(0, -4, -2)}) {
    EXPECT_DOUBLE_EQ(measure(grid(100), cam, {box(c, {0.5, 0.5, 0.5})}).viewport, 0.0)
        << c.transpose();
  }
  // A degenerate box (zero extents) projects to a point and marks at most one pixel.
  EXPECT_LE(measure(grid(100), cam, {box({0.01, 0.02, -2}, {0, 0, 0})}).viewport, 1.0 / 10000.0);
  // A non-finite state paints nothing.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_DOUBLE_EQ(measure(grid(100), cam, {box({nan, 0, -2}, {0.5, 0.5, 0.5})}).viewport, 0.0);
}

TEST(OcclusionMetric, BoxAcrossTheFrustumEdgeCoversItsVisiblePart) {
  // Centred on the right side plane at depth 2: NDC x in [0.75, 1.25] is cut to [0.75, 1], y in
  // +-0.25: share 0.25 x 0.5 / 4 = 0.03125. On a 96-pixel grid (NDC x -> 48 (x + 1)) that is
  // columns 84..95 and rows 36..59: 12 x 24 = 288 pixels.
  const Shares s = measure(grid(96), square_camera(), {plate(2.0, 0.0, 2.0, 0.5, 0.5)});
  const double pixels = 96.0 * 96.0;
  EXPECT_NEAR(s.viewport, 0.03125, 2.0 * 24.0 / pixels);
  EXPECT_NEAR(s.viewport, 288.0 / pixels, 0.5 / pixels);
}

TEST(OcclusionMetric, BoxFillingTheViewCoversEverything) {
  const Shares wall = measure(grid(100), square_camera(), {plate(0, 0, 2.0, 5.0, 5.0)});
  EXPECT_DOUBLE_EQ(wall.viewport, 1.0);
  EXPECT_DOUBLE_EQ(wall.central, 1.0);
  EXPECT_DOUBLE_EQ(wall.single, 1.0);
  // The eye inside a box: the clipped part reaches the near plane on every side.
  const Shares around = measure(grid(100), square_camera(), {box({0, 0, 0}, {5, 5, 5})});
  EXPECT_DOUBLE_EQ(around.viewport, 1.0);
}

TEST(OcclusionMetric, OverlapIsNotCountedTwice) {
  // On a 96-pixel grid NDC multiples of 1/8 fall on pixel boundaries (NDC x -> 48 (x + 1)).
  // A: NDC [-0.25, 0.25]^2, 24 x 24 = 576 pixels. B: x in [0.125, 0.375], y in +-0.125, 12 x 12
  // = 144 pixels, of which x in [0.125, 0.25] (6 columns) x 12 rows = 72 overlap A.
  const std::vector<FragmentState> frags{plate(0, 0, 2.0, 0.5, 0.5),
                                         plate(0.5, 0, 2.0, 0.25, 0.25)};
  const Shares s = measure(grid(96), square_camera(), frags);
  const double pixels = 96.0 * 96.0;
  EXPECT_NEAR(s.viewport, (576.0 + 144.0 - 72.0) / pixels, 0.5 / pixels);
  EXPECT_NEAR(s.single, 576.0 / pixels, 0.5 / pixels);  // the larger box alone
  // The central region is columns and rows 24..71 (2304 pixels) and holds all of both.
  EXPECT_NEAR(s.central, 648.0 / 2304.0, 0.5 / 2304.0);
}

TEST(OcclusionMetric, MeanAndMaxOverSteps) {
  // Same boxes as OverlapIsNotCountedTwice: A alone 576 pixels, A + B 648, nothing 0; a last step
  // whose near plane (2.5 m) has moved past both boxes (depth 2) also covers nothing.
  const double pixels = 96.0 * 96.0;
  const std::vector<FragmentState> a{plate(0, 0, 2.0, 0.5, 0.5)};
  const std::vector<FragmentState> ab{plate(0, 0, 2.0, 0.5, 0.5), plate(0.5, 0, 2.0, 0.25, 0.25)};
  const std::vector<FragmentState> none;
  const std::vector<FragmentState> wall{plate(0, 0, 2.0, 5.0, 5.0)};
  const CameraPose cam = square_camera();
  OcclusionMetric m(grid(96));
  m.begin(run_info(2, 4), snapshot(0, cam, wall));  // the initial snapshot is not in the series
  m.observe(snapshot(1, cam, a));
  m.observe(snapshot(2, cam, ab));
  m.observe(snapshot(3, cam, none));
  m.observe(snapshot(4, square_camera(2.5), ab));

  ASSERT_EQ(m.viewport_share_per_step().size(), 4u);
  ASSERT_EQ(m.central_share_per_step().size(), 4u);
  EXPECT_NEAR(m.viewport_share_per_step()[0], 576.0 / pixels, 1e-12);
  EXPECT_NEAR(m.viewport_share_per_step()[1], 648.0 / pixels, 1e-12);
  EXPECT_DOUBLE_EQ(m.viewport_share_per_step()[2], 0.0);
  EXPECT_DOUBLE_EQ(m.viewport_share_per_step()[3], 0.0);
  EXPECT_NEAR(m.central_share_per_step()[1], 648.0 / 2304.0, 1e-12);

  RunSummary s;
  m.fill(s);
  EXPECT_NEAR(s.occlusion.mean, (576.0 + 648.0) / pixels / 4.0, 1e-12);
  EXPECT_NEAR(s.occlusion.max, 648.0 / pixels, 1e-12);
  EXPECT_NEAR(s.occlusion.central_mean, (576.0 + 648.0) / 2304.0 / 4.0, 1e-12);
  EXPECT_NEAR(s.occlusion.central_max, 648.0 / 2304.0, 1e-12);
  EXPECT_NEAR(s.occlusion.single_fragment_max, 576.0 / pixels, 1e-12);

  // begin() starts a new run.
  m.begin(run_info(2, 1), snapshot(0, cam, none));
  EXPECT_TRUE(m.viewport_share_per_step().empty());
  RunSummary empty;
  m.fill(empty);
  EXPECT_DOUBLE_EQ(empty.occlusion.max, 0.0);
  EXPECT_DOUBLE_EQ(empty.occlusion.single_fragment_max, 0.0);
}

// Draws in a fixed order (arguments of one call are evaluated in an unspecified order), so the
// sample is the same with every compiler.
Eigen::Vector3d draw3(std::mt19937& rng, double lo, double hi) {
  std::uniform_real_distribution<double> u(lo, hi);
  const double x = u(rng);
  const double y = u(rng);
  const double z = u(rng);
  return {x, y, z};
}

Eigen::Matrix3d draw_rotation(std::mt19937& rng) {
  const Eigen::Vector3d v = draw3(rng, -1.0, 1.0);
  const double w = std::uniform_real_distribution<double>(-1.0, 1.0)(rng);
  return Eigen::Quaterniond(w, v.x(), v.y(), v.z()).normalized().toRotationMatrix();
}

// Reference: the ray through a pixel centre, from the near plane outwards, meets the box (slab
// test on the box's own axes). Equal to "the centre lies in the projected, clipped box's hull"
// because a convex body in front of the eye projects to a convex region of the rays that meet it.
bool ray_meets_box(const CameraPose& cam, const FragmentState& f, double ndc_x, double ndc_y) {
  const double tan_y = std::tan(0.5 * cam.fovy_deg * kPi / 180.0);
  const Eigen::Vector3d d(ndc_x * tan_y * cam.aspect, ndc_y * tan_y, 1.0);  // per metre of depth
  const Eigen::Vector3d c = cam.to_camera(f.position_m);
  double lo = cam.near_m;
  double hi = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d axis = cam.dir_to_camera(f.rotation.col(k));
    const double rate = axis.dot(d);  // s(z) = rate z - offset must stay within +-half
    const double offset = axis.dot(c);
    const double half = f.half_extents_m[k];
    if (rate == 0.0) {
      if (std::abs(offset) > half) return false;
      continue;
    }
    double z0 = (offset - half) / rate;
    double z1 = (offset + half) / rate;
    if (z0 > z1) std::swap(z0, z1);
    lo = std::max(lo, z0);
    hi = std::min(hi, z1);
  }
  return lo <= hi;
}

// The one fragment of `frags` on a 64-pixel-wide grid against `ray` (the reference through each
// pixel centre): the pixels the reference covers; each pixel where the metric disagrees adds one
// to `mismatches`.
template <class Ray>
int against_rays(const CameraPose& cam, const std::vector<FragmentState>& frags, Ray ray,
                 int& mismatches) {
  OcclusionMetric m(grid(64));
  m.begin(run_info(1, 1), snapshot(0, cam, frags));
  m.observe(snapshot(1, cam, frags));
  const int w = m.width_px();
  const int h = m.height_px();
  int covered_px = 0;
  for (int row = 0; row < h; ++row) {
    for (int col = 0; col < w; ++col) {
      const double ndc_x = (col + 0.5) / w * 2.0 - 1.0;
      const double ndc_y = 1.0 - (row + 0.5) / h * 2.0;
      const bool want = ray(cam, frags[0], ndc_x, ndc_y);
      covered_px += want ? 1 : 0;
      if (want != (m.coverage()[row * w + col] != 0)) ++mismatches;
    }
  }
  return covered_px;
}

TEST(OcclusionMetric, MatchesRayCastingReference) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> near_m(0.05, 1.05);
  CameraPose cam;  // 16:9, 60 degrees, eye off the origin, looking a little right and down
  cam.eye_m = Eigen::Vector3d(0.3, 1.6, 0.2);
  cam.forward = Eigen::Vector3d(0.2, -0.1, -1.0).normalized();
  cam.right = cam.forward.cross(Eigen::Vector3d::UnitY()).normalized();
  cam.up = cam.right.cross(cam.forward);
  int boxes = 0;
  int clipped = 0;
  int mismatches = 0;
  int covered_px = 0;
  for (int trial = 0; trial < 200; ++trial) {
    cam.near_m = near_m(rng);
    const Eigen::Vector3d local =
        draw3(rng, -1.0, 1.0).cwiseProduct(Eigen::Vector3d(1.5, 1.0, 1.5)) +
        Eigen::Vector3d(0, 0, 1.6);
    const Eigen::Vector3d centre =
        cam.eye_m + local.x() * cam.right + local.y() * cam.up + local.z() * cam.forward;
    const Eigen::Vector3d half = draw3(rng, 0.05, 0.45);
    const std::vector<FragmentState> frags{box(centre, half, draw_rotation(rng))};
    if (local.z() - half.norm() < cam.near_m) ++clipped;

    covered_px += against_rays(cam, frags, ray_meets_box, mismatches);
    ++boxes;
  }
  EXPECT_GT(clipped, 30);             // the sample does exercise the near-plane clip
  EXPECT_GT(covered_px, 20 * boxes);  // and is not mostly empty screens
  // Only a pixel centre within rounding of a hull edge could disagree.
  EXPECT_LE(mismatches, 2) << "over " << boxes << " boxes";
}

// ---- Convex pieces (FragmentState::shape).

// Reference for a hull: the ray through a pixel centre, from the near plane outwards, meets it
// (each face's half-space n . x <= d, moved to camera space, bounds the ray's depth on one side).
bool ray_meets_hull(const CameraPose& cam, const FragmentState& f, double ndc_x, double ndc_y) {
  const double tan_y = std::tan(0.5 * cam.fovy_deg * kPi / 180.0);
  const Eigen::Vector3d d(ndc_x * tan_y * cam.aspect, ndc_y * tan_y, 1.0);
  const Eigen::Vector3d c = cam.to_camera(f.position_m);
  double lo = cam.near_m;
  double hi = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < f.shape->faces.size(); ++i) {
    const Eigen::Vector3d n = cam.dir_to_camera(f.rotation * f.shape->normals[i]);
    const double limit = n.dot(c) + f.shape->offsets_m[i];  // n . (z d) <= limit
    const double rate = n.dot(d);
    if (rate == 0.0) {
      if (limit < 0.0) return false;
    } else if (rate > 0.0) {
      hi = std::min(hi, limit / rate);
    } else {
      lo = std::max(lo, limit / rate);
    }
  }
  return lo <= hi;
}

TEST(OcclusionMetric, HullsMatchRayCastingReference) {
  std::mt19937 rng(14);
  std::uniform_real_distribution<double> near_m(0.05, 1.05);
  std::uniform_real_distribution<double> size(0.1, 0.5);
  CameraPose cam;
  cam.eye_m = Eigen::Vector3d(0.3, 1.6, 0.2);
  cam.forward = Eigen::Vector3d(0.2, -0.1, -1.0).normalized();
  cam.right = cam.forward.cross(Eigen::Vector3d::UnitY()).normalized();
  cam.up = cam.right.cross(cam.forward);
  const double c3 = std::sqrt(3.0) / 2.0;
  int clipped = 0;
  int mismatches = 0;
  int covered_px = 0;
  for (int trial = 0; trial < 150; ++trial) {
    cam.near_m = near_m(rng);
    const double a = size(rng);
    const ConvexShape shape =
        trial % 3 == 0 ? test::regular_tetrahedron(a)
        : trial % 3 == 1
            ? test::box_hull(draw3(rng, 0.05, 0.45))
            : test::triangular_slab({{{a, 0.0}, {-0.5 * a, c3 * a}, {-0.5 * a, -c3 * a}}}, 0.02);
    const Eigen::Vector3d local =
        draw3(rng, -1.0, 1.0).cwiseProduct(Eigen::Vector3d(1.5, 1.0, 1.5)) +
        Eigen::Vector3d(0, 0, 1.6);
    const Eigen::Vector3d centre =
        cam.eye_m + local.x() * cam.right + local.y() * cam.up + local.z() * cam.forward;
    const std::vector<FragmentState> frags{
        test::shaped_fragment(shape, centre, draw_rotation(rng))};
    if (local.z() - shape.radius_m < cam.near_m) ++clipped;
    covered_px += against_rays(cam, frags, ray_meets_hull, mismatches);
  }
  EXPECT_GT(clipped, 20);
  EXPECT_GT(covered_px, 20 * 150);
  EXPECT_LE(mismatches, 2);  // only pixel centres within rounding of an edge
}

TEST(OcclusionMetric, CubeHullCoversWhatItsBoxCovers) {
  // The same cube as a box and as a hull, turned and placed at random, some across the near
  // plane: the projected, clipped polygon is the same up to rounding, so the pixel counts agree
  // but for a pixel centre within rounding of an edge. Tolerance: 1 pixel per fragment.
  std::mt19937 rng(5);
  const CameraPose cam = square_camera(0.5);
  int covered = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const ConvexShape cube = test::box_hull(draw3(rng, 0.05, 0.4));
    const Eigen::Vector3d centre =
        draw3(rng, -1.0, 1.0).cwiseProduct(Eigen::Vector3d(1, 1, 1)) + Eigen::Vector3d(0, 0, -1.2);
    const FragmentState hull = test::shaped_fragment(cube, centre, draw_rotation(rng));
    const double pixels = 100.0 * 100.0;
    const Shares as_hull = measure(grid(100), cam, {hull});
    const Shares as_box = measure(grid(100), cam, {test::as_box(hull)});
    EXPECT_NEAR(as_hull.viewport, as_box.viewport, 1.0 / pixels + 1e-12) << "trial " << trial;
    EXPECT_NEAR(as_hull.central, as_box.central, 1.0 / 2500.0 + 1e-12) << "trial " << trial;
    covered += as_box.viewport > 0.0;
  }
  EXPECT_GT(covered, 150);
}

TEST(OcclusionMetric, TriangularSlabCoversItsProjectedTriangle) {
  // An equilateral triangle of circumradius r = 0.5 m, 2 mm thick, centred on the view axis and
  // facing the 90-degree camera at depth 2 m: its front face (depth 1.999) projects to the
  // triangle of NDC circumradius rho = 0.5 / 1.999, and the back face to a smaller one inside it
  // (the view axis passes through both). Share: the triangle's area 3 sqrt(3) / 4 rho^2 over the
  // NDC square's 4 = 0.020318. On a 400 x 400 grid the pixel count differs from the area by
  // less than the boundary's pixels (perimeter 3 sqrt(3) rho * 200 = 260 px); the pixel rule,
  // counted here on the closed-form triangle, agrees exactly.
  const double r = 0.5;
  const double c3 = std::sqrt(3.0) / 2.0;
  const ConvexShape slab =
      test::triangular_slab({{{r, 0.0}, {-0.5 * r, c3 * r}, {-0.5 * r, -c3 * r}}}, 0.002);
  const Shares s =
      measure(grid(400), square_camera(), {test::shaped_fragment(slab, {0.0, 0.0, -2.0})});
  const double rho = r / 1.999;
  const double share = 3.0 * std::sqrt(3.0) / 4.0 * rho * rho / 4.0;
  EXPECT_NEAR(share, 0.020318, 1e-6);
  EXPECT_NEAR(s.viewport, share, 260.0 / 160000.0);
  // The pixel rule: centres inside the closed triangle with vertices rho (cos t, sin t), t = 0,
  // 120, 240 degrees, in pixels (200 + 200 x, 200 - 200 y).
  const std::array<Eigen::Vector2d, 3> v{{{200.0 + 200.0 * rho, 200.0},
                                          {200.0 - 100.0 * rho, 200.0 - 200.0 * c3 * rho},
                                          {200.0 - 100.0 * rho, 200.0 + 200.0 * c3 * rho}}};
  int inside = 0;
  for (int row = 0; row < 400; ++row) {
    for (int col = 0; col < 400; ++col) {
      const Eigen::Vector2d p(col + 0.5, row + 0.5);
      bool in = true;
      for (int i = 0; i < 3; ++i) {
        const Eigen::Vector2d a = v[static_cast<std::size_t>(i)];
        const Eigen::Vector2d b = v[static_cast<std::size_t>((i + 1) % 3)];
        const double side = (b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x());
        in = in && side <= 1e-9;  // the vertices run clockwise in y-down pixels
      }
      inside += in;
    }
  }
  EXPECT_NEAR(s.viewport * 160000.0, inside, 1.0);
}

}  // namespace
}  // namespace fragsim

namespace fragsim {
namespace {

// One step with these fragments drawn at these opacities (a fade frame).
Shares measure_faded(const MetricsDef& def, const CameraPose& cam,
                     const std::vector<FragmentState>& frags, const std::vector<float>& opacity) {
  OcclusionMetric m(def);
  const std::vector<FragmentState> none;
  m.begin(run_info(static_cast<int>(frags.size()), 1), snapshot(0, cam, none));
  StepSnapshot s = snapshot(1, cam, frags);
  s.opacity = opacity;
  m.observe(s);
  RunSummary r;
  m.fill(r);
  return {r.occlusion.mean, r.occlusion.central_mean, r.occlusion.single_fragment_max};
}

// The plate of FacingPlateCoversItsProjectedSquare: 676 pixels of the 100 x 100 grid.
constexpr double kPlatePixels = 676.0;

TEST(OcclusionMetric, TwoHalfTransparentFragmentsCompositeToThreeQuarters) {
  const FragmentState a = box({0, 0, -2}, {0.5, 0.5, 0.01});
  // Alone, opaque: the pixel rule's 676 pixels.
  const Shares alone = measure(grid(100, 0.5), square_camera(), {a});
  ASSERT_EQ(alone.viewport, kPlatePixels / 10000.0);
  // Half transparent: half of each pixel.
  const Shares half = measure_faded(grid(100, 0.5), square_camera(), {a}, {0.5f});
  EXPECT_NEAR(half.viewport, 0.5 * kPlatePixels / 10000.0, 1e-15);
  EXPECT_NEAR(half.single, 0.5 * kPlatePixels / 10000.0, 1e-15);
  // The same plate twice at 0.5: 1 - (1 - 0.5)(1 - 0.5) = 0.75 on every one of its pixels.
  const Shares twice = measure_faded(grid(100, 0.5), square_camera(), {a, a}, {0.5f, 0.5f});
  EXPECT_NEAR(twice.viewport, 0.75 * kPlatePixels / 10000.0, 1e-15);
  EXPECT_NEAR(twice.single, 0.5 * kPlatePixels / 10000.0, 1e-15);
  // Two that overlap in part: 0.5 where one covers, 0.75 on the overlap. The counts come from
  // the opaque metric (the union and each alone), the overlap by inclusion-exclusion.
  const FragmentState c = box({0.3, 0, -2}, {0.5, 0.5, 0.01});
  const double n_a = measure(grid(100, 0.5), square_camera(), {a}).viewport * 10000.0;
  const double n_c = measure(grid(100, 0.5), square_camera(), {c}).viewport * 10000.0;
  const double n_union = measure(grid(100, 0.5), square_camera(), {a, c}).viewport * 10000.0;
  const double n_overlap = n_a + n_c - n_union;
  ASSERT_GT(n_overlap, 100.0);
  ASSERT_LT(n_overlap, n_a);
  const Shares part = measure_faded(grid(100, 0.5), square_camera(), {a, c}, {0.5f, 0.5f});
  EXPECT_NEAR(part.viewport, (0.5 * (n_union - n_overlap) + 0.75 * n_overlap) / 10000.0, 1e-14);
}

TEST(OcclusionMetric, InvisibleFragmentCoversNothingAndOpaqueFrameIsUnchanged) {
  const FragmentState a = box({0, 0, -2}, {0.5, 0.5, 0.01});
  const FragmentState c = box({0.3, 0.1, -3}, {0.4, 0.3, 0.2});
  const Shares none = measure_faded(grid(100, 0.5), square_camera(), {a}, {0.0f});
  EXPECT_EQ(none.viewport, 0.0);
  EXPECT_EQ(none.central, 0.0);
  EXPECT_EQ(none.single, 0.0);
  // Opacities of 1 give the opaque metric's numbers to the bit (1 - prod(1 - 1) is exactly 1).
  const Shares opaque = measure(grid(100, 0.5), square_camera(), {a, c});
  const Shares ones = measure_faded(grid(100, 0.5), square_camera(), {a, c}, {1.0f, 1.0f});
  EXPECT_EQ(ones.viewport, opaque.viewport);
  EXPECT_EQ(ones.central, opaque.central);
  EXPECT_EQ(ones.single, opaque.single);
  // A fragment at 0.25 over an opaque one adds nothing where the opaque one already covers.
  const Shares over = measure_faded(grid(100, 0.5), square_camera(), {a, a}, {1.0f, 0.25f});
  EXPECT_EQ(over.viewport, kPlatePixels / 10000.0);
}

}  // namespace
}  // namespace fragsim
