// A small task system for fragsim's controller on std::thread, to copy or to learn from: what a
// game's job system does for fragsim_controller_def's enqueue_task and finish_task.
//
//   FragsimThreadPool pool(4);               // 3 threads, and the thread that steps is the 4th
//   fragsim_controller_def def = fragsim_default_controller_def();
//   pool.install(def);                       // enqueue_task, finish_task, worker_count
//   fragsim_controller_create(&def, ...);    // the pool must outlive the controller
//
// enqueue_task cuts [0, item_count) into about four ranges per worker (none shorter than
// min_range) and wakes the threads; finish_task makes the calling thread worker 0, takes ranges
// until none is left, then waits for the ranges the threads took. One task at a time: the
// controller finishes each task before it enqueues the next, and one pool serves one controller
// step at a time. A step allocates nothing here: the ranges are handed out by an atomic counter.
#pragma once

#include <fragsim/control.h>

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

class FragsimThreadPool {
 public:
  // workers in [1, FRAGSIM_MAX_WORKERS]: workers - 1 threads plus the caller of finish_task.
  explicit FragsimThreadPool(int workers) : workers_(std::clamp(workers, 1, FRAGSIM_MAX_WORKERS)) {
    for (int w = 1; w < workers_; ++w) threads_.emplace_back([this, w] { serve(w); });
  }
  ~FragsimThreadPool() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_all();
    for (std::thread& t : threads_) t.join();
  }
  FragsimThreadPool(const FragsimThreadPool&) = delete;
  FragsimThreadPool& operator=(const FragsimThreadPool&) = delete;

  void install(fragsim_controller_def& def) {
    def.enqueue_task = &FragsimThreadPool::enqueue;
    def.finish_task = &FragsimThreadPool::finish;
    def.user_task_context = this;
    def.worker_count = workers_;
  }
  int workers() const { return workers_; }

 private:
  static void* enqueue(fragsim_task_fn* task, int32_t item_count, int32_t min_range,
                       void* task_context, void* user) {
    auto& pool = *static_cast<FragsimThreadPool*>(user);
    const int32_t wanted = std::max<int32_t>(1, item_count / (4 * pool.workers_));
    const int32_t range = std::max(min_range, wanted);
    {
      std::unique_lock<std::mutex> lock(pool.mutex_);
      // A thread that woke late for the last task may still be looking for a range of it: the
      // task's fields change only when no thread is inside work().
      pool.idle_.wait(lock, [&pool] { return pool.active_ == 0; });
      pool.task_ = task;
      pool.context_ = task_context;
      pool.items_ = item_count;
      pool.range_ = range;
      pool.ranges_ = (item_count + range - 1) / range;
      pool.next_.store(0, std::memory_order_relaxed);
      pool.done_ = 0;
      ++pool.generation_;
    }
    pool.wake_.notify_all();
    return &pool;
  }

  static void finish(void* handle, void* user) {
    (void)handle;
    auto& pool = *static_cast<FragsimThreadPool*>(user);
    const int taken = pool.work(0);
    std::unique_lock<std::mutex> lock(pool.mutex_);
    pool.done_ += taken;
    pool.idle_.wait(lock, [&pool] { return pool.done_ == pool.ranges_; });
  }

  // Takes ranges as worker w until none is left; returns how many it ran.
  int work(int w) {
    int ran = 0;
    for (;;) {
      const int32_t k = next_.fetch_add(1, std::memory_order_relaxed);
      if (k >= ranges_) return ran;
      const int32_t begin = k * range_;
      const int32_t end = std::min(items_, begin + range_);
      task_(begin, end, static_cast<uint32_t>(w), context_);
      ++ran;
    }
  }

  void serve(int w) {
    std::uint64_t seen = 0;
    for (;;) {
      {
        std::unique_lock<std::mutex> lock(mutex_);
        wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
        if (stopping_) return;
        seen = generation_;
        ++active_;
      }
      const int ran = work(w);
      std::lock_guard<std::mutex> lock(mutex_);
      done_ += ran;
      --active_;
      idle_.notify_all();
    }
  }

  const int workers_;
  std::vector<std::thread> threads_;
  std::mutex mutex_;
  std::condition_variable wake_;
  std::condition_variable idle_;  // a range done, or a thread out of work()
  bool stopping_ = false;
  std::uint64_t generation_ = 0;
  // The task in flight. Written under the mutex while no thread is inside work(), and read by the
  // threads inside work(), which they enter under the mutex: no race.
  fragsim_task_fn* task_ = nullptr;
  void* context_ = nullptr;
  int32_t items_ = 0;
  int32_t range_ = 1;
  int32_t ranges_ = 0;
  std::atomic<int32_t> next_{0};
  int done_ = 0;    // ranges run
  int active_ = 0;  // threads inside work()
};
