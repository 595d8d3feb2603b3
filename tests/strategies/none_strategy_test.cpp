// `none` on one fragment fired along a known line at a still camera
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

TEST(NoneStrategy, FragmentAtTheLensHitsAndFliesStraight) {
  const Outcome o = run(test::single_fragment(kAtLens), "none");
  EXPECT_EQ(o.summary.intersections.near_fragments, 1);
  EXPECT_EQ(o.summary.intersections.camera_hit_fragments, 1);
  for (const auto& step : o.rec.steps) {
    EXPECT_TRUE(step.forces.empty());
    // No gravity, no contact: x and y never change, the speed stays 10 m/s.
    EXPECT_NEAR(step.fragments[0].position_m.x(), 0.03, 1e-12);
    EXPECT_NEAR(step.fragments[0].position_m.y(), 1.62, 1e-12);
    EXPECT_NEAR(step.fragments[0].velocity_mps.z(), 10.0, 1e-12);
  }
}

}  // namespace
}  // namespace fragsim
