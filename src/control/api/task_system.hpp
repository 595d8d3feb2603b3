#pragma once
// The game's task system (fragsim_controller_def.enqueue_task, finish_task) as the strategies'
// ParallelFor. A task system is the game's code, and a range it runs on a worker index it did not
// announce, or items it never runs, would corrupt a step silently, so each range is checked on its
// way in and the items are counted; a step whose ranges did not cover its items exactly once on
// valid workers is failed by the controller (broken()), never returned as if whole.

#include <atomic>
#include <cstdint>

#include "control/strategies/parallel_for.hpp"
#include "fragsim/control.h"

namespace fragsim::control {

class TaskSystem final : public ParallelFor {
 public:
  // A def with both task functions set (checked before).
  explicit TaskSystem(const fragsim_controller_def& def)
      : enqueue_(def.enqueue_task),
        finish_(def.finish_task),
        user_(def.user_task_context),
        workers_(def.worker_count) {}

  int worker_count() const override { return workers_; }
  void run(std::int32_t item_count, std::int32_t min_range, RangeFn fn,
           void* context) const override;

  // Clears the record of misbehaviour; call before a step.
  void begin_step() const { broken_.store(false, std::memory_order_relaxed); }
  // Whether a run since begin_step() ran a range on a worker index out of range, or did not run
  // every item exactly once.
  bool broken() const { return broken_.load(std::memory_order_relaxed); }

 private:
  struct Job {
    RangeFn fn;
    void* context;
    std::int32_t workers;
    std::atomic<std::int64_t> items_done{0};
    std::atomic<bool> bad_range{false};
  };
  static void call(std::int32_t begin, std::int32_t end, std::uint32_t worker, void* job);

  fragsim_enqueue_task_fn* enqueue_;
  fragsim_finish_task_fn* finish_;
  void* user_;
  std::int32_t workers_;
  mutable std::atomic<bool> broken_{false};
};

}  // namespace fragsim::control
