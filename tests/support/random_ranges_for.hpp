#pragma once
// A ParallelFor for tests: each run() cuts its items into uneven ranges drawn from a seeded
// random generator and runs them on real threads, which take the ranges in whatever order they
// get to them. A strategy whose answers depend on how its work was split, or on which worker ran
// what, shows it here.

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <random>
#include <thread>
#include <utility>
#include <vector>

#include "control/strategies/parallel_for.hpp"

namespace fragsim::test {

class RandomRangesFor final : public ParallelFor {
 public:
  RandomRangesFor(int workers, std::uint32_t seed) : workers_(workers), rng_(seed) {}

  int worker_count() const override { return workers_; }

  // Ranges of at least min_range items (a shorter one only when all the items are fewer), the
  // calling thread as worker 0 and workers - 1 threads started for the call.
  void run(std::int32_t item_count, std::int32_t min_range, RangeFn fn,
           void* context) const override {
    if (item_count <= 0) return;
    const std::vector<std::pair<std::int32_t, std::int32_t>> ranges =
        random_ranges(item_count, std::max(min_range, std::int32_t{1}));
    ++runs_;
    if (ranges.size() > 1) ++split_runs_;
    std::atomic<std::size_t> next{0};
    const auto work = [&](std::uint32_t worker) {
      for (std::size_t r = next++; r < ranges.size(); r = next++) {
        fn(ranges[r].first, ranges[r].second, worker, context);
      }
    };
    std::vector<std::thread> threads;
    for (int w = 1; w < workers_; ++w) threads.emplace_back(work, static_cast<std::uint32_t>(w));
    work(0);
    for (std::thread& t : threads) t.join();
  }

  // How many run() calls there were, and how many of them cut their items into several ranges.
  int runs() const { return runs_; }
  int split_runs() const { return split_runs_; }

 private:
  // [begin, end) ranges covering [0, count), each of min_range to a third of count items (or
  // what is left), so that both tiny and large ranges occur.
  std::vector<std::pair<std::int32_t, std::int32_t>> random_ranges(std::int32_t count,
                                                                   std::int32_t min_range) const {
    std::vector<std::pair<std::int32_t, std::int32_t>> ranges;
    const std::int32_t longest = std::max(min_range, count / 3);
    std::uniform_int_distribution<std::int32_t> length(min_range, longest);
    for (std::int32_t begin = 0; begin < count;) {
      std::int32_t end = std::min(count, begin + length(rng_));
      if (count - end < min_range) end = count;  // no range shorter than min_range at the end
      ranges.emplace_back(begin, end);
      begin = end;
    }
    return ranges;
  }

  int workers_;
  mutable std::mt19937 rng_;
  mutable int runs_ = 0;
  mutable int split_runs_ = 0;
};

}  // namespace fragsim::test
