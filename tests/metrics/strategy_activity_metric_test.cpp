// What the strategy did, counted over three hand-made steps: candidates, forces and their impulse
// and largest acceleration, caps, guards, deferrals, wall contacts and the near distance in force.

#include "metrics/strategy_activity_metric.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "metrics/run_summary.hpp"

namespace fragsim {
namespace {

constexpr double kDt_s = 0.5;

// Two fragments of 2 kg and 1 kg.
std::vector<FragmentState> two_fragments() {
  std::vector<FragmentState> f(2);
  f[0].mass_kg = 2.0;
  f[1].mass_kg = 1.0;
  return f;
}

TEST(StrategyActivityMetric, CountsWhatTheStrategyDidStepByStep) {
  const std::vector<FragmentState> frags = two_fragments();
  StrategyActivityMetric metric(24, 10.0);
  StepSnapshot snap;
  snap.fragments = frags;
  snap.camera.near_m = 0.1;
  metric.begin({nullptr, "edge", 2, 3, kDt_s}, snap);

  // Step 1: both are candidates; 5 N on fragment 0 (2.5 m/s^2), reduced by the cap; a guard and
  // two wall contacts.
  const std::vector<int> both{0, 1};
  const std::vector<AppliedForce> push0{{0, {3.0, 4.0, 0.0}}};
  const std::vector<int> capped0{0};
  snap.step = 1;
  snap.candidates = both;
  snap.forces = push0;
  snap.capped = capped0;
  snap.guarded = 1;
  snap.wall_contacts = 2;
  metric.observe(snap);

  // Step 2: fragment 1 alone, 6 N on 1 kg (6 m/s^2); three fragments deferred; near pulled in.
  const std::vector<int> one{1};
  const std::vector<AppliedForce> push1{{1, {0.0, 0.0, -6.0}}};
  snap = {};
  snap.fragments = frags;
  snap.step = 2;
  snap.camera.near_m = 0.05;
  snap.candidates = one;
  snap.forces = push1;
  snap.deferred = 3;
  metric.observe(snap);

  // Step 3: nothing.
  snap = {};
  snap.fragments = frags;
  snap.step = 3;
  snap.camera.near_m = 0.1;
  metric.observe(snap);

  EXPECT_EQ(metric.candidates_per_step(), (std::vector<int>{2, 1, 0}));
  EXPECT_EQ(metric.near_per_step_m(), (std::vector<double>{0.1, 0.05, 0.1}));
  EXPECT_TRUE(metric.was_capped(0));
  EXPECT_FALSE(metric.was_capped(1));

  RunSummary s;
  metric.fill(s);
  EXPECT_EQ(s.activity.candidates_initial, 2);
  EXPECT_EQ(s.activity.candidates_max, 2);
  EXPECT_EQ(s.activity.candidate_steps, 3);
  EXPECT_EQ(s.activity.capped_forces, 1);
  EXPECT_EQ(s.activity.guarded, 1);
  EXPECT_EQ(s.activity.deferred, 3);
  EXPECT_EQ(s.activity.wall_contacts, 2);
  EXPECT_EQ(s.activity.forced_fragments, 2);
  EXPECT_NEAR(s.activity.impulse_Ns, 5.0 * kDt_s + 6.0 * kDt_s, 1e-12);
  EXPECT_NEAR(s.activity.max_accel_mps2, 6.0, 1e-12);
  EXPECT_EQ(s.activity.min_near_m, 0.05);
  // Depth step at 10 m with a 24-bit buffer and the near plane at 0.05 m: 10^2 / (0.05 2^24).
  EXPECT_NEAR(s.activity.depth_step_m, 100.0 / (0.05 * 16777216.0), 1e-15);
}

TEST(StrategyActivityMetric, RunWithoutStepsReportsNothing) {
  const std::vector<FragmentState> frags = two_fragments();
  StrategyActivityMetric metric(24, 10.0);
  StepSnapshot snap;
  snap.fragments = frags;
  metric.begin({nullptr, "none", 2, 0, kDt_s}, snap);
  RunSummary s;
  s.activity.candidates_max = 7;  // overwritten
  metric.fill(s);
  EXPECT_EQ(s.activity.candidates_initial, 0);
  EXPECT_EQ(s.activity.candidates_max, 0);
  EXPECT_EQ(s.activity.forced_fragments, 0);
  EXPECT_EQ(s.activity.impulse_Ns, 0.0);
  EXPECT_EQ(s.activity.min_near_m, 0.0);
  EXPECT_EQ(s.activity.depth_step_m, 0.0);  // no near distance, no depth step
}

}  // namespace
}  // namespace fragsim
