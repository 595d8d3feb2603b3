// `wall` on one fragment fired along a known line at a still camera
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

TEST(WallStrategy, IncomingFragmentBouncesOffTheWall) {
  const Outcome o = run(test::single_fragment(kAtLens), "wall");
  // It arrives at +10 m/s along z and leaves the wall moving away from the camera.
  EXPECT_LT(o.rec.steps.back().fragments[0].velocity_mps.z(), 0.0);
  // The wall's far face is at 0.625 m: the box never comes closer than that, give or take ODE's
  // contact layer and one step's penetration.
  double closest_m = 1e9;
  for (const auto& step : o.rec.steps)
    closest_m = std::min(closest_m, -step.fragments[0].position_m.z());
  EXPECT_GT(closest_m, 0.5);
  EXPECT_EQ(o.summary.intersections.near_fragments, 0);
  EXPECT_EQ(o.summary.intersections.camera_hit_fragments, 0);
}

}  // namespace
}  // namespace fragsim
