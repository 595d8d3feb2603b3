// `deflect-all` on one fragment fired along a known line at a still camera
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

TEST(DeflectAllStrategy, PushesApproachingFragmentsAwayFromTheAxis) {
  const Outcome right = run(test::single_fragment({0.5, 1.6, -5.0}), "deflect-all");
  int pushes = 0;
  for (const auto& step : right.rec.steps) {
    for (const AppliedForce& f : step.forces) {
      ++pushes;
      EXPECT_GT(f.force_N.x(), 0.0);  // right of the axis: pushed further right
      EXPECT_NEAR(f.force_N.y(), 0.0, 1e-12);
    }
  }
  EXPECT_GT(pushes, 0);
  // Out of range (6 m) at the start: no push in the first step.
  const Outcome far = run(test::single_fragment({0.5, 1.6, -10.0}), "deflect-all");
  EXPECT_TRUE(far.rec.steps[1].forces.empty());
}

TEST(DeflectAllStrategy, RecedingFragmentIsLeftAlone) {
  const Outcome o = run(test::single_fragment({0.5, 1.6, -3.0}, -10.0), "deflect-all");
  for (const auto& step : o.rec.steps) EXPECT_TRUE(step.forces.empty());
}

}  // namespace
}  // namespace fragsim
