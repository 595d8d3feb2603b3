// `edge` on one fragment fired along a known line at a still camera
// (support/single_fragment_runs.hpp), and its replanning after a bounce.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

#include "geometry/depth_buffer.hpp"
#include "metrics/near_plane_metric.hpp"
#include "sim/scene_strategies.hpp"
#include "sim/simulation.hpp"
#include "strategies/near_plane_strategy.hpp"
#include "support/single_fragment_runs.hpp"
#include "support/test_scenes.hpp"

namespace fragsim {
namespace {

using test::kAtLens;
using test::kBeside;
using test::run;
using Outcome = test::RecordedRun;

TEST(EdgeStrategy, FragmentAtTheLensIsPushedToTheNearestEdgeAndMisses) {
  const Outcome o = run(test::single_fragment(kAtLens), "edge");
  // A candidate from the prediction at t = 0.
  ASSERT_GT(o.rec.steps.size(), 1u);
  ASSERT_EQ(o.rec.steps[1].candidates.size(), 1u);
  // It crosses the near plane at (0.03, 0.02): the top edge (0.038 away) is nearer than the right
  // one (0.073), so every push is straight up.
  int pushes = 0;
  for (const auto& step : o.rec.steps) {
    for (const AppliedForce& f : step.forces) {
      ++pushes;
      EXPECT_GT(f.force_N.y(), 0.0);
      EXPECT_EQ(f.force_N.x(), 0.0);
      EXPECT_EQ(f.force_N.z(), 0.0);
    }
  }
  EXPECT_GT(pushes, 0);
  EXPECT_EQ(o.summary.intersections.near_fragments, 0);
  EXPECT_EQ(o.summary.intersections.camera_hit_fragments, 0);
}

TEST(EdgeStrategy, FragmentNearTheRightEdgeIsPushedRight) {
  const Outcome o = run(test::single_fragment({0.09, 1.601, -10.0}), "edge");
  int pushes = 0;
  for (const auto& step : o.rec.steps) {
    for (const AppliedForce& f : step.forces) {
      ++pushes;
      EXPECT_GT(f.force_N.x(), 0.0);
      EXPECT_EQ(f.force_N.y(), 0.0);
    }
  }
  EXPECT_GT(pushes, 0);
  EXPECT_EQ(o.summary.intersections.near_fragments, 0);
}

TEST(EdgeStrategy, FragmentTwoMetresAsideIsNeverACandidate) {
  // The thesis ball: V_c (t_G - t) + radii = 1 m/s * 1.5 s + 0.27 m < 2 m, with t_G the cap of
  // 1.5 s (zero gravity: the path never comes down; the default 3 s cap would give 3.27 m).
  Scene scene = test::single_fragment(kBeside);
  scene.strategies.edge.horizon_cap_s = 1.5;
  const Outcome o = run(scene, "edge");
  for (const auto& step : o.rec.steps) {
    EXPECT_TRUE(step.candidates.empty());
    EXPECT_TRUE(step.forces.empty());
  }
}

TEST(EdgeStrategy, ZeroGainReproducesNoneExactly) {
  Scene scene = test::single_fragment(kAtLens);
  scene.strategies.edge.k = 0.0;
  const Outcome edge = run(scene, "edge");
  const Outcome none = run(scene, "none");
  ASSERT_EQ(edge.rec.steps.size(), none.rec.steps.size());
  for (std::size_t k = 0; k < edge.rec.steps.size(); ++k) {
    EXPECT_EQ(edge.rec.steps[k].fragments[0].position_m, none.rec.steps[k].fragments[0].position_m);
  }
}

TEST(EdgeStrategy, AccelerationCapHolds) {
  Scene scene = test::single_fragment(kAtLens);
  scene.strategies.edge.k = 1e9;
  scene.strategies.edge.a_max_mps2 = 50.0;
  const Outcome o = run(scene, "edge");
  const double mass_kg = 600.0 * 0.1 * 0.1 * 0.1;
  for (const auto& step : o.rec.steps) {
    for (const AppliedForce& f : step.forces)
      EXPECT_LE(f.force_N.norm(), mass_kg * 50.0 * (1 + 1e-12));
  }
}

// Thrown down and toward the camera from 3 m up, 6 m ahead: at t = 0 its path comes down through
// the camera's height after 0.2 s, 4.8 m away, so it is no candidate (ball radius 0.2 s * 1 m/s
// + 0.27 m). It bounces off the ground 3.6 m ahead (no friction: it keeps its 6 m/s toward the
// camera) and rises to 0.74 m, so for a while its path enters the reachable ball again.
Scene bouncing_fragment(Replan replan) {
  Scene s = test::single_fragment({0.03, 3.0, -6.0}, 6.0 * std::sqrt(2.0));
  s.explosion.offset_m = {0.0, 1.0, -1.0};  // push down and toward the camera
  s.sim.gravity_mps2 = {0.0, -9.81, 0.0};
  s.ground.enabled = true;
  s.ground.restitution = 0.5;
  s.ground.friction = 0.0;  // keeps its speed toward the camera through the bounce
  s.sim.duration_s = 2.0;
  s.strategies.edge.replan = replan;
  return s;
}

int candidate_steps(const Scene& scene) {
  auto s = make_strategy("edge", scene);
  test::Recorder rec;
  const std::array<RunObserver*, 1> obs{&rec};
  simulate(scene, *s, obs);
  int n = 0;
  for (const auto& step : rec.steps) n += static_cast<int>(step.candidates.size());
  EXPECT_TRUE(rec.steps[1].candidates.empty()) << "a candidate at t = 0";
  return n;
}

TEST(EdgeStrategy, ReplanNeverIgnoresTheBounceContactAndAlwaysSeeIt) {
  EXPECT_EQ(candidate_steps(bouncing_fragment(Replan::kNever)), 0);
  EXPECT_GT(candidate_steps(bouncing_fragment(Replan::kContact)), 0);
  EXPECT_GT(candidate_steps(bouncing_fragment(Replan::kAlways)), 0);
}

}  // namespace
}  // namespace fragsim
