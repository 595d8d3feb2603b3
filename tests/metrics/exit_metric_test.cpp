// ExitMetric on hand-built snapshots. The camera sits at the origin looking down world -z (so a
// camera-space point (x, y, z) is the world point (x, y, -z)), fovy 60 deg, aspect 16:9: at depth z
// the screen spans |y| <= 0.577 z and |x| <= 1.026 z. The near rectangle at 0.1 m is
// +-0.103 x +-0.058 m. Counts are exact; no tolerance is needed.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <utility>
#include <vector>

#include "metrics/exit_metric.hpp"
#include "metrics/run_summary.hpp"
#include "support/convex_shapes.hpp"

namespace fragsim {
namespace {

constexpr double kDt_s = 1.0 / 60.0;

// Camera-space centre paths, one per fragment, each sampled at step 0, 1, ...; plus, per step,
// the fragments the physics reported as touching the camera and the camera pose.
struct Script {
  std::vector<std::vector<Eigen::Vector3d>> paths_m;
  std::vector<std::vector<int>> camera_hits;  // index = step; may be shorter than the run
  std::vector<CameraPose> cameras;            // index = step; default pose where missing
  std::vector<std::vector<int>> pushed{};     // index = step: fragments given a force then
};

FragmentState fragment_at_camera(const Eigen::Vector3d& c_m) {
  FragmentState f;
  f.position_m = {c_m.x(), c_m.y(), -c_m.z()};
  f.half_extents_m = {0.05, 0.05, 0.05};
  f.radius_m = std::sqrt(3.0) * 0.05;
  return f;
}

ExitMetric play(const Script& script, double near_miss_m = 1.0) {
  MetricsDef def;
  def.near_miss_m = near_miss_m;
  ExitMetric metric(def);
  const std::size_t n = script.paths_m.size();
  const std::size_t snapshots = script.paths_m.front().size();
  std::vector<FragmentState> states(n);
  const std::vector<int> no_hits;
  std::vector<AppliedForce> forces;

  auto snapshot = [&](std::size_t k) {
    for (std::size_t i = 0; i < n; ++i) states[i] = fragment_at_camera(script.paths_m[i][k]);
    StepSnapshot snap;
    snap.step = static_cast<int>(k);
    snap.t_s = static_cast<double>(k) * kDt_s;
    if (k < script.cameras.size()) snap.camera = script.cameras[k];
    snap.camera_body_half_m = {0.15, 0.1, 0.15};
    snap.fragments = states;
    snap.camera_hits = k < script.camera_hits.size() ? script.camera_hits[k] : no_hits;
    forces.clear();
    if (k < script.pushed.size()) {
      for (int i : script.pushed[k]) forces.push_back({i, Eigen::Vector3d(0.0, 1.0, 0.0)});
    }
    snap.forces = forces;
    return snap;
  };

  const RunInfo info{nullptr, "test", static_cast<int>(n), static_cast<int>(snapshots) - 1, kDt_s};
  metric.begin(info, snapshot(0));
  for (std::size_t k = 1; k < snapshots; ++k) metric.observe(snapshot(k));
  metric.end();
  return metric;
}

Exit exit_of(const std::vector<Eigen::Vector3d>& path_m) {
  return play({{path_m}, {}, {}}).exit(0);
}

TEST(ExitMetric, UpThroughTheTop) {
  // Depth 5: half height 2.887 m, so y = 4 is past the top and |x| stays well inside.
  EXPECT_EQ(exit_of({{0, 0, 5}, {0, 2, 5}, {0, 4, 5}, {0, 6, 5}}), Exit::kTop);
}

TEST(ExitMetric, DownThroughTheBottom) {
  EXPECT_EQ(exit_of({{0.5, 0, 5}, {0.5, -2, 5}, {0.5, -4, 5}}), Exit::kBottom);
}

TEST(ExitMetric, SidewaysThroughLeftAndRight) {
  // Depth 5: half width 5.132 m.
  EXPECT_EQ(exit_of({{0, 1, 5}, {-3, 1, 5}, {-6, 1, 5}}), Exit::kLeft);
  EXPECT_EQ(exit_of({{0, -1, 5}, {3, -1, 5}, {6, -1, 5}}), Exit::kRight);
}

TEST(ExitMetric, BorderExceededMostWins) {
  // Off both borders at once: x / 5.132 = 1.07 and y / 2.887 = 1.39, so the top.
  EXPECT_EQ(exit_of({{0, 0, 5}, {5.5, 4, 5}}), Exit::kTop);
  // x / 5.132 = 1.36 and y / 2.887 = 1.04, so the right.
  EXPECT_EQ(exit_of({{0, 0, 5}, {7, 3, 5}}), Exit::kRight);
}

TEST(ExitMetric, StraightAtTheEyeIsANearExit) {
  // Along the view axis and on behind the eye.
  EXPECT_EQ(exit_of({{0, 0, 5}, {0, 0, 2}, {0, 0, -1}, {0, 0, -4}}), Exit::kNear);
  // Stopped in front of the eye but short of the near plane.
  EXPECT_EQ(exit_of({{0, 0, 5}, {0, 0, 0.05}}), Exit::kNear);
}

TEST(ExitMetric, StayingOnScreenIsStayed) {
  EXPECT_EQ(exit_of({{0, 0, 5}, {0.5, 0.5, 4}, {1, 1, 3}}), Exit::kStayed);
}

TEST(ExitMetric, NeverOnScreenCountsNowhere) {
  // Behind the eye throughout, then off to the side beyond the border.
  const ExitMetric m =
      play({{{{0, 0, -5}, {0, 1, -5}, {0, 2, -5}}, {{20, 0, 5}, {25, 0, 5}, {30, 0, 5}}}, {}, {}});
  EXPECT_EQ(m.exit(0), Exit::kNone);
  EXPECT_EQ(m.exit(1), Exit::kNone);
  RunSummary s;
  m.fill(s);
  EXPECT_EQ(
      s.exits.top + s.exits.bottom + s.exits.left + s.exits.right + s.exits.near + s.exits.stayed,
      0);
}

TEST(ExitMetric, LastExitCounts) {
  // Out at the left, back in, out at the top.
  EXPECT_EQ(exit_of({{0, 0, 5}, {-6, 0, 5}, {0, 0, 5}, {0, 4, 5}}), Exit::kTop);
  // Out at the left, back in and still on screen at the end.
  EXPECT_EQ(exit_of({{0, 0, 5}, {-6, 0, 5}, {0, 0, 5}}), Exit::kStayed);
}

TEST(ExitMetric, EnteringLaterAndLeavingCounts) {
  EXPECT_EQ(exit_of({{-8, 0, 5}, {-4, 0, 5}, {0, 0, 5}, {0, -4, 5}}), Exit::kBottom);
}

TEST(ExitMetric, UsesEachSnapshotsCamera) {
  // The fragment stays put at world (0, 0, -5); the camera pans 60 deg to the right, which puts
  // the fragment at camera x = -4.33 m, depth 2.5 m (half width 2.566 m): gone past the left.
  Script script{{{{0, 0, 5}, {0, 0, 5}}}, {}, {CameraPose{}, CameraPose{}}};
  const double yaw = 60.0 * kPi / 180.0;
  script.cameras[1].forward = {std::sin(yaw), 0.0, -std::cos(yaw)};
  script.cameras[1].right = {std::cos(yaw), 0.0, std::sin(yaw)};
  EXPECT_EQ(play(script).exit(0), Exit::kLeft);
}

TEST(ExitMetric, FillCountsEachKind) {
  const ExitMetric m = play({{{{0, 0, 5}, {0, 4, 5}},     // top
                              {{0, 0, 5}, {0, -4, 5}},    // bottom
                              {{0, 0, 5}, {0, -4, 5}},    // bottom
                              {{0, 0, 5}, {-6, 0, 5}},    // left
                              {{0, 0, 5}, {6, 0, 5}},     // right
                              {{0, 0, 5}, {0, 0, -1}},    // near
                              {{0, 0, 5}, {0, 0, 6}},     // stayed
                              {{0, 0, -5}, {0, 0, -6}}},  // never on screen
                             {},
                             {}},
                            0.1);
  RunSummary s;
  m.fill(s);
  EXPECT_EQ(s.exits.top, 1);
  EXPECT_EQ(s.exits.bottom, 2);
  EXPECT_EQ(s.exits.left, 1);
  EXPECT_EQ(s.exits.right, 1);
  EXPECT_EQ(s.exits.near, 1);
  EXPECT_EQ(s.exits.stayed, 1);
  EXPECT_EQ(s.intersections.near_misses, 0);
}

TEST(ExitMetric, ExitNamesForCsv) {
  EXPECT_EQ(exit_name(Exit::kNone), "none");
  EXPECT_EQ(exit_name(Exit::kTop), "top");
  EXPECT_EQ(exit_name(Exit::kBottom), "bottom");
  EXPECT_EQ(exit_name(Exit::kLeft), "left");
  EXPECT_EQ(exit_name(Exit::kRight), "right");
  EXPECT_EQ(exit_name(Exit::kNear), "near");
  EXPECT_EQ(exit_name(Exit::kStayed), "stayed");
}

TEST(ExitMetric, FastPassBesideTheEyeBetweenSnapshots) {
  // 0.5 m beside the eye at depth 0, reached only between the two snapshots: both samples are
  // over 3 m from the eye. The box (half 0.05 m) stays 0.45 m from the axis, clear of the near
  // rectangle (0.103 m) and of the camera body (0.15 m).
  const std::vector<Eigen::Vector3d> path_m{{0.5, 0, 3}, {0.5, 0, -3}};
  for (const auto& p : path_m) ASSERT_GT(p.norm(), 1.0);
  const ExitMetric m = play({{path_m}, {}, {}}, 1.0);
  EXPECT_TRUE(m.near_miss(0));
  EXPECT_FALSE(m.touched(0));
  RunSummary s;
  m.fill(s);
  EXPECT_EQ(s.intersections.near_misses, 1);
}

TEST(ExitMetric, SlowPassWithinTheDistance) {
  EXPECT_TRUE(play({{{{0, 0.8, 3}, {0, 0.8, 0.5}, {0, 0.8, -1}}}, {}, {}}, 1.0).near_miss(0));
}

TEST(ExitMetric, ThroughTheNearRectangleIsNoMiss) {
  const ExitMetric m = play({{{{0, 0, 3}, {0, 0, -3}}}, {}, {}}, 1.0);
  EXPECT_TRUE(m.touched(0));
  EXPECT_FALSE(m.near_miss(0));
  RunSummary s;
  m.fill(s);
  EXPECT_EQ(s.intersections.near_misses, 0);
}

TEST(ExitMetric, ReportedCameraHitIsNoMiss) {
  // The same geometric fly-by as above, but the physics' sensor saw it touch the camera.
  const ExitMetric m = play({{{{0.5, 0, 3}, {0.5, 0, -3}}}, {{}, {0}}, {}}, 1.0);
  EXPECT_TRUE(m.touched(0));
  EXPECT_FALSE(m.near_miss(0));
}

TEST(ExitMetric, TwoMetresAwayIsNoMiss) {
  const ExitMetric m = play({{{{2, 0, 3}, {2, 0, -3}}}, {}, {}}, 1.0);
  EXPECT_FALSE(m.near_miss(0));
  EXPECT_FALSE(m.touched(0));
}

TEST(ExitMetric, CountsFragmentsNotSteps) {
  // One fragment passes close twice, one once, one far away.
  const ExitMetric m = play({{{{0.5, 0, 3}, {0.5, 0, -3}, {0.5, 0, 3}},
                              {{0, 0.6, 4}, {0, 0.6, 2}, {0, 0.6, -2}},
                              {{3, 0, 4}, {3, 0, 2}, {3, 0, -2}}},
                             {},
                             {}},
                            1.0);
  RunSummary s;
  m.fill(s);
  EXPECT_EQ(s.intersections.near_misses, 2);
}

TEST(ExitMetric, TetrahedronBesideTheLensIsANearMissWhereItsBoxWouldTouch) {
  // The tetrahedron of circumradius R = 6 cm right of the lens, vertex 0 pointing away (+x), its
  // centre at x = w + 0.01 + R / 3 (w the near half width): its nearest vertices miss the near
  // rectangle by 1 cm, its centre passes x = 0.13 m from the eye: a near miss. Its body box, which
  // reaches R to the left, would meet the rectangle and spoil it.
  const double r = 0.06;
  const ConvexShape t = test::regular_tetrahedron(r / std::sqrt(3.0));
  const double w = 0.1 * std::tan(30.0 * kPi / 180.0) * 16.0 / 9.0;
  const double x = w + 0.01 + r / 3.0;
  const Eigen::Matrix3d rot =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::Ones(), Eigen::Vector3d::UnitX())
          .toRotationMatrix();
  const auto run = [&](const FragmentState& piece) {
    MetricsDef def;
    def.near_miss_m = 1.0;
    ExitMetric metric(def);
    std::vector<FragmentState> frag{piece};
    StepSnapshot snap;
    snap.camera_body_half_m = Eigen::Vector3d::Constant(0.001);
    snap.fragments = frag;
    const std::vector<double> depths{0.5, 0.25, 0.0, -0.25};
    frag[0].position_m = {x, 0.0, -depths[0]};
    metric.begin({nullptr, "test", 1, 3, kDt_s}, snap);
    for (std::size_t k = 1; k < depths.size(); ++k) {
      frag[0].position_m = {x, 0.0, -depths[k]};
      snap.step = static_cast<int>(k);
      metric.observe(snap);
    }
    return std::pair{metric.near_miss(0), metric.touched(0)};
  };
  const FragmentState piece = test::shaped_fragment(t, Eigen::Vector3d::Zero(), rot);
  EXPECT_EQ(run(piece), std::pair(true, false));
  EXPECT_EQ(run(test::as_box(piece)), std::pair(false, true));
}

// The exits of the pushed fragments alone: fragments 1 and 2 get a force at step 1, 3 at step 2
// (never on screen), 0 none; so of the top, bottom and left exits only the bottom and the left
// are the pushed fragments', and the pushed one never on screen is in no column.
TEST(ExitMetric, PushedExitsCountOnlyFragmentsGivenAForce) {
  Script script{{{{0, 0, 5}, {0, 4, 5}, {0, 6, 5}},      // top
                 {{0, 0, 5}, {0, -4, 5}, {0, -6, 5}},    // bottom
                 {{0, 0, 5}, {-6, 0, 5}, {-8, 0, 5}},    // left
                 {{0, 0, -5}, {0, 0, -6}, {0, 0, -7}}},  // behind the eye throughout
                {},
                {},
                {{}, {1, 2}, {3}}};
  const ExitMetric m = play(script);
  EXPECT_FALSE(m.pushed(0));
  EXPECT_TRUE(m.pushed(1));
  EXPECT_TRUE(m.pushed(3));
  RunSummary s;
  m.fill(s);
  EXPECT_EQ(s.exits.top, 1);
  EXPECT_EQ(s.pushed_exits.top, 0);
  EXPECT_EQ(s.pushed_exits.bottom, 1);
  EXPECT_EQ(s.pushed_exits.left, 1);
  EXPECT_EQ(s.pushed_exits.right + s.pushed_exits.near + s.pushed_exits.stayed, 0);
}

}  // namespace
}  // namespace fragsim
