// `near-plane` on one fragment fired along a known line at a still camera
// (support/single_fragment_runs.hpp).

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

TEST(NearPlaneStrategy, NearPlaneComesInWhileAFragmentPassesAndGoesBackOut) {
  // Passes 0.13 m right of the eye: its 0.05 m half-box reaches into the near rectangle (half
  // width 0.1026 m at 0.1 m) but misses a 0.1 m camera body. Pulling the near plane in to 0.01 m
  // (half width 0.0103 m) lets it pass uncut.
  Scene scene = test::single_fragment({0.13, 1.6, -10.0});
  scene.camera.body_size_m = {0.1, 0.1, 0.1};
  EXPECT_EQ(run(scene, "none").summary.intersections.near_fragments, 1);
  const Outcome o = run(scene, "near-plane");
  double min_near = 1.0;
  for (const auto& step : o.rec.steps) min_near = std::min(min_near, step.near_m);
  EXPECT_LT(min_near, 0.1);
  EXPECT_GE(min_near, scene.strategies.near_plane.min_near_m);
  EXPECT_EQ(o.rec.steps.front().near_m, 0.1);
  EXPECT_EQ(o.rec.steps.back().near_m, 0.1);  // it has flown past
  EXPECT_EQ(o.summary.intersections.near_fragments, 0);
}

TEST(NearPlaneStrategy, DepthStep) {
  // z^2 / (n 2^b): 10 m with the near plane at 0.1 m and 24 bits.
  EXPECT_NEAR(depth_step_m(10.0, 0.1, 24), 100.0 / (0.1 * 16777216.0), 1e-15);
}

}  // namespace
}  // namespace fragsim
