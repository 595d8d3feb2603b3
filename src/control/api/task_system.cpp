#include "control/api/task_system.hpp"

#include <algorithm>

namespace fragsim::control {

void TaskSystem::call(std::int32_t begin, std::int32_t end, std::uint32_t worker, void* job) {
  Job& j = *static_cast<Job*>(job);
  // A range outside the items, or on a worker whose work space does not exist, is not run, as
  // running it would write out of bounds. The step then fails (broken()).
  if (worker >= static_cast<std::uint32_t>(j.workers) || begin < 0 || end < begin) {
    j.bad_range.store(true, std::memory_order_relaxed);
    return;
  }
  j.fn(begin, end, worker, j.context);
  j.items_done.fetch_add(end - begin, std::memory_order_relaxed);
}

void TaskSystem::run(std::int32_t item_count, std::int32_t min_range, RangeFn fn,
                     void* context) const {
  if (item_count <= 0) return;
  Job job{fn, context, workers_};
  void* task =
      enqueue_(&TaskSystem::call, item_count, std::max<std::int32_t>(min_range, 1), &job, user_);
  if (task != nullptr) finish_(task, user_);
  // finish_task (or enqueue_task, for a task it ran at once) synchronises with every range, so
  // the counts are final here.
  if (job.bad_range.load(std::memory_order_relaxed) ||
      job.items_done.load(std::memory_order_relaxed) != item_count) {
    broken_.store(true, std::memory_order_relaxed);
  }
}

}  // namespace fragsim::control
