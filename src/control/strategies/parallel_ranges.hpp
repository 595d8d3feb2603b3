#pragma once
// A callable over ranges of items through a ParallelFor (parallel_for.hpp), whose ranges are a
// plain function and a context pointer, so the callable is the context, a captureless lambda the
// function.

#include <cstdint>

#include "control/strategies/parallel_for.hpp"

namespace fragsim {

// Calls body(begin, end, worker) over [0, item_count), in ranges of at least min_range items on
// `parallel`'s workers, or as one range on worker 0 (the calling thread) when parallel is nullptr.
// Returns when every range is done.
template <class Body>
void for_ranges(const ParallelFor* parallel, std::int32_t item_count, std::int32_t min_range,
                const Body& body) {
  if (item_count <= 0) return;
  if (parallel == nullptr) {
    body(std::int32_t{0}, item_count, std::uint32_t{0});
    return;
  }
  parallel->run(
      item_count, min_range,
      [](std::int32_t begin, std::int32_t end, std::uint32_t worker, void* context) {
        (*static_cast<const Body*>(context))(begin, end, worker);
      },
      const_cast<void*>(static_cast<const void*>(&body)));
}

}  // namespace fragsim
