// The game's task system as the strategies' ParallelFor (api/task_system.cpp), driven by stand-in
// task systems: one that runs every range at once, and ones that misbehave (skip a range, run one
// on a worker that does not exist), which must break the step rather than pass it as whole.

#include "control/api/task_system.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace {

using fragsim::control::TaskSystem;

// What the stand-in task system saw and how it misbehaves.
struct Game {
  std::vector<std::pair<std::int32_t, std::int32_t>> ranges;
  std::int32_t min_range = -1;
  int enqueued = 0;
  int finished = 0;
  bool skip_last = false;
  std::uint32_t worker = 0;  // the worker index every range runs on
};

// Runs the ranges of min_range items in order, then returns a handle finish_task waits on.
void* enqueue(fragsim_task_fn* task, std::int32_t item_count, std::int32_t min_range,
              void* task_context, void* user) {
  Game& g = *static_cast<Game*>(user);
  ++g.enqueued;
  g.min_range = min_range;
  for (std::int32_t begin = 0; begin < item_count; begin += min_range) {
    const std::int32_t end = std::min(begin + min_range, item_count);
    if (g.skip_last && end == item_count) break;
    g.ranges.emplace_back(begin, end);
    task(begin, end, g.worker, task_context);
  }
  return &g;
}

void finish(void* task, void* user) {
  EXPECT_EQ(task, user);
  ++static_cast<Game*>(user)->finished;
}

fragsim_controller_def def_for(Game& g) {
  fragsim_controller_def def = fragsim_default_controller_def();
  def.enqueue_task = enqueue;
  def.finish_task = finish;
  def.user_task_context = &g;
  def.worker_count = 2;
  return def;
}

// Counts how often each item ran.
void count_runs(std::int32_t begin, std::int32_t end, std::uint32_t, void* context) {
  auto& runs = *static_cast<std::vector<int>*>(context);
  for (std::int32_t i = begin; i < end; ++i) ++runs[static_cast<std::size_t>(i)];
}

TEST(TaskSystem, EveryItemRunsOnceThroughTheGamesTasks) {
  Game g;
  const TaskSystem ts(def_for(g));
  EXPECT_EQ(ts.worker_count(), 2);
  std::vector<int> runs(10, 0);
  ts.begin_step();
  ts.run(10, 3, count_runs, &runs);
  EXPECT_EQ(g.enqueued, 1);
  EXPECT_EQ(g.finished, 1);
  EXPECT_EQ(g.min_range, 3);
  const std::vector<std::pair<std::int32_t, std::int32_t>> ranges = {
      {0, 3}, {3, 6}, {6, 9}, {9, 10}};
  EXPECT_EQ(g.ranges, ranges);
  EXPECT_EQ(runs, std::vector<int>(10, 1));
  EXPECT_FALSE(ts.broken());
  // No items: the game is not asked; a min_range below 1 reaches it as 1.
  ts.run(0, 3, count_runs, &runs);
  EXPECT_EQ(g.enqueued, 1);
  ts.run(2, 0, count_runs, &runs);
  EXPECT_EQ(g.min_range, 1);
  EXPECT_FALSE(ts.broken());
}

TEST(TaskSystem, ASkippedRangeBreaksTheStepUntilTheNext) {
  Game g;
  g.skip_last = true;
  const TaskSystem ts(def_for(g));
  std::vector<int> runs(10, 0);
  ts.begin_step();
  ts.run(10, 4, count_runs, &runs);  // runs [0, 4) and [4, 8), skips [8, 10)
  EXPECT_EQ(runs, (std::vector<int>{1, 1, 1, 1, 1, 1, 1, 1, 0, 0}));
  EXPECT_TRUE(ts.broken());
  ts.begin_step();
  EXPECT_FALSE(ts.broken());
  g.skip_last = false;
  ts.run(10, 4, count_runs, &runs);
  EXPECT_FALSE(ts.broken());
}

TEST(TaskSystem, ARangeOnAWorkerThatDoesNotExistIsNotRun) {
  Game g;
  g.worker = 2;  // worker_count is 2: indices 0 and 1 only
  const TaskSystem ts(def_for(g));
  std::vector<int> runs(5, 0);
  ts.begin_step();
  ts.run(5, 5, count_runs, &runs);
  EXPECT_EQ(runs, std::vector<int>(5, 0));
  EXPECT_TRUE(ts.broken());
}

}  // namespace
