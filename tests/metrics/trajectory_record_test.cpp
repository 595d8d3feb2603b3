// The trajectory record on hand-built runs (support/hand_runs.hpp): every snapshot's positions,
// step 0 included, and a fresh record at each begin().

#include "metrics/trajectory_record.hpp"

#include <gtest/gtest.h>

#include "support/hand_runs.hpp"

namespace fragsim {
namespace {

using test::make_run;
using test::play;
using test::record;
using test::Trajectory;

TEST(TrajectoryRecord, StoresEverySnapshotIncludingStepZero) {
  const Trajectory run = make_run(3, 4);
  const TrajectoryRecord ref = record(run);
  EXPECT_EQ(ref.steps(), 5);
  EXPECT_EQ(ref.fragments(), 3);
  for (int k = 0; k <= 4; ++k) {
    for (int i = 0; i < 3; ++i) {
      const auto& expected = run[static_cast<std::size_t>(k)][static_cast<std::size_t>(i)];
      EXPECT_EQ(ref.position(k, i), expected.position_m) << "step " << k << " fragment " << i;
      EXPECT_EQ(ref.at_step(k)[static_cast<std::size_t>(i)], expected.position_m);
    }
  }
}

TEST(TrajectoryRecord, BeginStartsAFreshRecord) {
  TrajectoryRecord ref;
  play(make_run(3, 4), ref);
  play(make_run(2, 1), ref);
  EXPECT_EQ(ref.steps(), 2);
  EXPECT_EQ(ref.fragments(), 2);
  EXPECT_EQ(ref.position(1, 1), make_run(2, 1)[1][1].position_m);
}

}  // namespace
}  // namespace fragsim
