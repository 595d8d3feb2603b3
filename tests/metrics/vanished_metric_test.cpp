// Vanished fragments and the near-plane metric in a fade frame: hand-placed boxes before a camera
// at the origin looking down -z with the default frustum (near 0.1 m, half width 0.10264 m, half
// height 0.05774 m), each snapshot given its opacities.

#include "metrics/vanished_metric.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <span>
#include <vector>

#include "metrics/near_plane_metric.hpp"
#include "support/test_scenes.hpp"

namespace fragsim {
namespace {

FragmentState box_at(const Eigen::Vector3d& p, double half_m = 0.01) {
  return test::box_at(p, half_m);
}

struct Frame {
  Eigen::Vector3d position_m;
  float opacity = 1.0f;
};

// Runs both metrics over one fragment's frames (the first is the initial snapshot, drawn opaque
// as the simulation's step 0 is) and returns the summary they fill.
RunSummary run(const std::vector<Frame>& frames, bool with_opacity = true) {
  NearPlaneMetric near;
  VanishedMetric vanished;
  std::vector<FragmentState> frag{box_at(frames[0].position_m)};
  std::vector<float> opacity{1.0f};
  StepSnapshot snap;
  snap.camera_body_half_m = Eigen::Vector3d::Constant(0.001);
  snap.fragments = frag;
  const RunInfo info{nullptr, "test", 1, static_cast<int>(frames.size()) - 1, 1.0 / 60.0};
  near.begin(info, snap);
  vanished.begin(info, snap);
  for (std::size_t k = 1; k < frames.size(); ++k) {
    frag[0] = box_at(frames[k].position_m);
    opacity[0] = frames[k].opacity;
    snap.step = static_cast<int>(k);
    snap.opacity = with_opacity ? std::span<const float>(opacity) : std::span<const float>();
    near.observe(snap);
    vanished.observe(snap);
  }
  RunSummary s;
  near.fill(s);
  vanished.fill(s, near);
  return s;
}

// Straight through the near rectangle's centre between two frames (z = -0.2 to +0.2).
TEST(VanishedMetric, InvisibleCrossingIsNoIntersectionButVanished) {
  // Opaque: the swept test counts it.
  const RunSummary opaque = run({{{0, 0, -1.0}}, {{0, 0, -0.2}}, {{0, 0, 0.2}}}, false);
  EXPECT_EQ(opaque.intersections.near_fragments, 1);
  EXPECT_EQ(opaque.intersections.vanished_fragments, 0);
  // Invisible at the end of the crossing step: nothing drawn at the plane.
  const RunSummary end0 = run({{{0, 0, -1.0}, 1.0f}, {{0, 0, -0.2}, 0.3f}, {{0, 0, 0.2}, 0.0f}});
  EXPECT_EQ(end0.intersections.near_fragments, 0);
  EXPECT_EQ(end0.intersections.near_fragment_steps, 0);
  EXPECT_EQ(end0.intersections.vanished_fragments,
            1);  // and it dropped below half, in view, at z = -0.2
  // Invisible at the start of it (it faded out before; it is counted once).
  const RunSummary start0 = run({{{0, 0, -1.0}, 1.0f}, {{0, 0, -0.2}, 0.0f}, {{0, 0, 0.2}, 0.4f}});
  EXPECT_EQ(start0.intersections.near_fragments, 0);
  EXPECT_EQ(start0.intersections.vanished_fragments, 1);
  // Faint but drawn at both ends: a cut shows, so it is an intersection.
  const RunSummary faint = run({{{0, 0, -1.0}, 1.0f}, {{0, 0, -0.2}, 0.1f}, {{0, 0, 0.2}, 0.1f}});
  EXPECT_EQ(faint.intersections.near_fragments, 1);
  EXPECT_EQ(faint.intersections.vanished_fragments, 1);  // faded in view all the same
}

// Invisible when it crosses, but it never dropped through one half in view: it came in invisible
// from the side. The crossing alone makes it vanished.
TEST(VanishedMetric, CrossingInvisibleCountsEvenWithoutADropInView) {
  const RunSummary s = run(
      {{{0, 0, -1.0}, 1.0f}, {{5.0, 0, -0.2}, 0.0f}, {{0, 0, -0.1}, 0.0f}, {{0, 0, 0.2}, 0.0f}});
  EXPECT_EQ(s.intersections.near_fragments, 0);
  EXPECT_EQ(s.intersections.vanished_fragments, 1);
}

TEST(VanishedMetric, DropBelowHalfCountsOnlyInViewAndOnce) {
  // In the middle of the view at 0.6 m: 1 -> 0.4.
  EXPECT_EQ(run({{{0, 0, -2.0}}, {{0, 0, -0.6}, 0.4f}}).intersections.vanished_fragments, 1);
  // Exactly one half is not below it.
  EXPECT_EQ(run({{{0, 0, -2.0}}, {{0, 0, -0.6}, 0.5f}}).intersections.vanished_fragments, 0);
  // Far outside the view (2 m to the right at 0.6 m depth, where the half width is 0.62 m).
  EXPECT_EQ(run({{{2.0, 0, -2.0}}, {{2.0, 0, -0.6}, 0.4f}}).intersections.vanished_fragments, 0);
  // Behind the eye.
  EXPECT_EQ(run({{{0, 0, 2.0}}, {{0, 0, 0.6}, 0.0f}}).intersections.vanished_fragments, 0);
  // Down, up and down again: one fragment, counted once.
  EXPECT_EQ(run({{{0, 0, -2.0}}, {{0, 0, -0.6}, 0.4f}, {{0, 0, -0.9}, 0.9f}, {{0, 0, -0.6}, 0.3f}})
                .intersections.vanished_fragments,
            1);
  // Opaque frames (every strategy but fade): nothing vanishes.
  EXPECT_EQ(run({{{0, 0, -2.0}}, {{0, 0, -0.6}, 0.0f}}, false).intersections.vanished_fragments, 0);
}

}  // namespace
}  // namespace fragsim
