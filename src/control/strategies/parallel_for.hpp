#pragma once
// How a strategy runs its per-fragment work, either in ranges on the game's workers (the C API's
// task system) or all on the calling thread. A strategy that uses it writes each item's answer to
// the item's own place and gathers them in item order afterwards, so that no answer depends on how
// the ranges fall or which worker ran them.

#include <cstdint>

namespace fragsim {

class ParallelFor {
 public:
  // A range [begin, end) of items on worker `worker`, in [0, worker_count()).
  using RangeFn = void (*)(std::int32_t begin, std::int32_t end, std::uint32_t worker,
                           void* context);

  virtual ~ParallelFor() = default;
  // The workers ranges may run on at once; a strategy keeps one work space per worker.
  virtual int worker_count() const = 0;
  // Calls fn over [0, item_count) in ranges of at least min_range items and returns when every
  // range is done.
  virtual void run(std::int32_t item_count, std::int32_t min_range, RangeFn fn,
                   void* context) const = 0;
};

// Everything on the calling thread, as one range.
class SerialFor final : public ParallelFor {
 public:
  int worker_count() const override { return 1; }
  void run(std::int32_t item_count, std::int32_t min_range, RangeFn fn,
           void* context) const override {
    (void)min_range;
    if (item_count > 0) fn(0, item_count, 0, context);
  }
};

}  // namespace fragsim
