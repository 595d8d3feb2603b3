// Several cameras' answers joined into one per fragment (api/joint_push.cpp), without edge-min's
// probe: as for edge and deflect-all, the cameras' forces are added, candidates and capped
// fragments listed once, guarded and deferred summed, rejected_cheaply the least; and nothing of a
// join is left for the next. Numbers by hand.

#include "control/api/joint_push.hpp"

#include <gtest/gtest.h>

#include <array>
#include <vector>

namespace {

using fragsim::AppliedForce;
using fragsim::FragmentState;
using fragsim::StepContext;
using fragsim::StepOutput;
using fragsim::control::JointPush;

std::vector<int> list(const fragsim::ResourceVector<int>& v) {
  return {v.begin(), v.end()};
}

TEST(JointPush, WithoutAProbeTheCamerasForcesAreAdded) {
  JointPush join(fragsim::default_memory_resource());
  EXPECT_FALSE(join.has_probe());
  join.reserve(3);
  const std::vector<FragmentState> fragments(3);
  const std::array<StepContext, 2> contexts{};
  StepOutput a;
  a.forces.push_back({0, {1.0, 0.0, 0.0}});
  a.forces.push_back({2, {0.0, 0.0, -1.5}});
  a.activity.candidates = {0, 2};
  a.activity.capped = {2};
  a.activity.guarded = 2;
  a.activity.deferred = 1;
  a.activity.rejected_cheaply = 1;
  StepOutput b;
  b.forces.push_back({0, {0.0, 2.0, 0.25}});
  b.activity.candidates = {0};
  b.activity.guarded = 1;
  b.activity.rejected_cheaply = 2;
  const std::array<const StepOutput*, 2> outs{&a, &b};

  StepOutput out;
  const JointPush::Conflicts c = join.join(contexts, outs, fragments, out);
  EXPECT_EQ(c.count, 0);
  EXPECT_EQ(c.first, -1);
  ASSERT_EQ(out.forces.size(), 2u);
  EXPECT_EQ(out.forces[0].fragment, 0);
  EXPECT_EQ(out.forces[0].force_N, Eigen::Vector3d(1.0, 2.0, 0.25));  // sums of exact numbers
  EXPECT_EQ(out.forces[1].fragment, 2);
  EXPECT_EQ(out.forces[1].force_N, Eigen::Vector3d(0.0, 0.0, -1.5));
  EXPECT_EQ(list(out.activity.candidates), (std::vector<int>{0, 2}));
  EXPECT_EQ(list(out.activity.capped), (std::vector<int>{2}));
  EXPECT_EQ(out.activity.guarded, 3);
  EXPECT_EQ(out.activity.deferred, 1);
  EXPECT_EQ(out.activity.rejected_cheaply, 1);

  // The next join starts clean: only camera b's answer now.
  const std::array<const StepOutput*, 1> only_b{&b};
  StepOutput next;
  join.join(std::span<const StepContext>(contexts.data(), 1), only_b, fragments, next);
  ASSERT_EQ(next.forces.size(), 1u);
  EXPECT_EQ(next.forces[0].fragment, 0);
  EXPECT_EQ(next.forces[0].force_N, Eigen::Vector3d(0.0, 2.0, 0.25));
  EXPECT_EQ(list(next.activity.candidates), (std::vector<int>{0}));
  EXPECT_TRUE(next.activity.capped.empty());
  EXPECT_EQ(next.activity.guarded, 1);
  EXPECT_EQ(next.activity.rejected_cheaply, 2);
}

}  // namespace
