// The controller's cost by phase of the explosion, timed inside a real run: what a game feels in
// its worst frames, not the median step. Each step the strategy is timed right where a game calls
// it (after the previous physics step, on the states that step left), then a floor loop reads the
// same fragment states with a plain conservative test, in the same process: a loaded machine
// slows both, so their ratio is what to read.
//
//   worst_frame SCENE STRATEGY [REPEATS] [--workers N] [section.key=value ...]
//               [--shadow section.key=value ...]
//
// Phases by step (the default scene at dt 1/60 s): t = 0 is step 0, early flight steps 1-29, the
// lens pass steps 30-59 (the debris passing the camera), landed the last 60 steps. Per phase:
// the mean and the 95th percentile (nearest rank) of the strategy's thread CPU time per fragment
// per step, the floor's mean, and over steps 1-59 (the flight) the mean and p95 the issue's
// targets name; then the worst step, the strategy's share of the physics over the run, the
// allocations made inside the strategy's steps and the page faults of its first step (both in
// the first run of the process, as a game's first explosion meets them). Each other figure is
// the median over REPEATS runs (default 5). FRAGSIM_WORST_FRAME_CSV=FILE writes the last
// repeat's per-step times (step,strategy_ns,floor_ns,physics_ns per fragment, ...).
//
// --shadow: a second copy of the strategy, made with these settings on top of the run's, is
// stepped on the same states every step, its answers thrown away, and timed the same way; the
// figures then add its cost and the strategy's cost beyond it, step by step. `--shadow
// edge-min.max_solves=1` leaves edge-min its rejection, the ranking of what it left and one exact
// solve a step, so the cost beyond the shadow is at most what the other exact solves cost. The
// two take turns going first (the strategy on even steps), so that neither always finds the
// states already in the cache.
//
// The strategy steps into its own reserved output, copied to the run's outside the timing, so the
// run's own buffers growing is not counted as the strategy's.
//
// --workers N: the strategy (and its shadow) is given a ParallelFor of N workers, the calling
// thread and N - 1 threads of a pool started before the runs, as a game's task system would
// (StepContext::parallel), and told so once (Strategy::set_worker_count). Its steps are then
// timed by the wall clock, as the calling thread's CPU time would miss the workers' (compare N = 1
// with N = 2, both on the wall clock, not with a run without the option); the figures add the
// flight's and the lens pass's mean and p95 per step in microseconds. The floor stays on the
// calling thread's CPU time.

#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <mutex>
#include <new>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "control/geometry/work_space.hpp"
#include "control/strategies/parallel_for.hpp"
#include "io/atomic_file.hpp"
#include "sim/run.hpp"
#include "sim/scene_file.hpp"
#include "sim/scene_strategies.hpp"
#include "strategies/scene_strategy.hpp"

namespace {

// Allocations counted while `counting` is set: the strategy's steps only.
std::atomic<long> allocations{0};
std::atomic<bool> counting{false};

}  // namespace

// GCC pairs the replaced operator new with free() only through the call below and warns that
// free() does not match new; both sides of the pair are these functions, so it does.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void* operator new(std::size_t size) {
  if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
// The strategies' vectors may come through the aligned forms.
void* operator new(std::size_t size, std::align_val_t align) {
  if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1, std::memory_order_relaxed);
  const auto a = static_cast<std::size_t>(align);
  if (void* p = std::aligned_alloc(a, (std::max<std::size_t>(size, 1) + a - 1) / a * a)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p, std::align_val_t) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t, std::align_val_t) noexcept {
  std::free(p);
}
#pragma GCC diagnostic pop

namespace {

double thread_cpu_ns() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return 1e9 * static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec);
}

double wall_ns() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return 1e9 * static_cast<double>(ts.tv_sec) + static_cast<double>(ts.tv_nsec);
}

// A game's task system in miniature: workers - 1 threads started once, asleep between runs, and
// the calling thread as worker 0. Each run cuts its items into about four ranges per worker (at
// least min_range items each) that the workers take in turn; run() returns when all are done.
// Nothing in a run allocates.
class ThreadPoolFor final : public fragsim::ParallelFor {
 public:
  explicit ThreadPoolFor(int workers) : workers_(std::max(workers, 1)) {
    for (int w = 1; w < workers_; ++w) {
      threads_.emplace_back([this, w] { serve(static_cast<std::uint32_t>(w)); });
    }
  }
  ~ThreadPoolFor() override {
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_all();
    for (std::thread& t : threads_) t.join();
  }
  ThreadPoolFor(const ThreadPoolFor&) = delete;
  ThreadPoolFor& operator=(const ThreadPoolFor&) = delete;

  int worker_count() const override { return workers_; }
  void run(std::int32_t item_count, std::int32_t min_range, RangeFn fn,
           void* context) const override {
    if (item_count <= 0) return;
    const std::int32_t wanted = std::max<std::int32_t>(1, 4 * workers_);
    const std::int32_t length =
        std::max({std::int32_t{1}, min_range, (item_count + wanted - 1) / wanted});
    const std::int32_t ranges = (item_count + length - 1) / length;
    if (ranges == 1 || workers_ == 1) {
      fn(0, item_count, 0, context);
      return;
    }
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      job_ = Job{fn, context, item_count, length, ranges};
      next_.store(0);
      done_ = 0;
      ++generation_;
    }
    wake_.notify_all();
    const std::int32_t mine = take_ranges(0, job_);
    std::unique_lock<std::mutex> lock(mutex_);
    done_ += mine;
    // Every range done, and no worker still inside the job, before the next one may be set.
    finished_.wait(lock, [&] { return done_ == job_.ranges && active_ == 0; });
  }

 private:
  struct Job {
    RangeFn fn = nullptr;
    void* context = nullptr;
    std::int32_t items = 0;
    std::int32_t length = 0;
    std::int32_t ranges = 0;
  };

  // Runs ranges of `job` until none is left; returns how many it ran.
  std::int32_t take_ranges(std::uint32_t worker, const Job& job) const {
    std::int32_t ran = 0;
    for (std::int32_t r = next_.fetch_add(1); r < job.ranges; r = next_.fetch_add(1)) {
      const std::int32_t begin = r * job.length;
      job.fn(begin, std::min(job.items, begin + job.length), worker, job.context);
      ++ran;
    }
    return ran;
  }

  void serve(std::uint32_t worker) const {
    long seen = 0;
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
      wake_.wait(lock, [&] { return stopping_ || generation_ != seen; });
      if (stopping_) return;
      seen = generation_;
      if (done_ == job_.ranges) continue;  // woken after the job was done: nothing to join
      const Job job = job_;
      ++active_;
      lock.unlock();
      const std::int32_t ran = take_ranges(worker, job);
      lock.lock();
      done_ += ran;
      --active_;
      if (done_ == job.ranges && active_ == 0) finished_.notify_one();
    }
  }

  int workers_;
  std::vector<std::thread> threads_;
  mutable std::mutex mutex_;
  mutable std::condition_variable wake_;
  mutable std::condition_variable finished_;
  mutable Job job_;
  mutable std::atomic<std::int32_t> next_{0};
  mutable std::int32_t done_ = 0;    // ranges of the job done
  mutable std::int32_t active_ = 0;  // workers inside the job
  mutable long generation_ = 0;
  bool stopping_ = false;
};

long minor_faults() {
  rusage usage{};
  getrusage(RUSAGE_THREAD, &usage);
  return usage.ru_minflt + usage.ru_majflt;
}

// What one step cost, in ns for the whole step.
struct StepTimes {
  double strategy_ns = 0.0;
  double shadow_ns = 0.0;  // --shadow's copy (0 without one)
  double floor_ns = 0.0;
  long faults = 0;
  long allocations = 0;
  int survivors = 0;   // fragments the strategy's cheap tests left to an exact solve
  int candidates = 0;  // fragments it found threatening
};

// A plain pass over the fragment states with a conservative test: a fragment is certainly clear
// when it is farther from the eye than its speed relative to the camera, gravity and the camera's
// own speed can bring it over the horizon. Reads what any strategy must read, does no more.
int floor_pass(const fragsim::StepContext& ctx, double reach_m, double horizon_s) {
  const Eigen::Vector3d eye = ctx.camera.eye_m;
  const double g_m = 0.5 * ctx.gravity_mps2.norm() * horizon_s * horizon_s;
  const double vc_m = std::isfinite(ctx.camera_max_speed_mps)
                          ? std::max(0.0, ctx.camera_max_speed_mps) * horizon_s
                          : 0.0;
  int doubtful = 0;
  for (const fragsim::FragmentState& f : ctx.fragments) {
    const double d_m = (f.position_m - eye).norm();
    const double travel_m = (f.velocity_mps - ctx.camera_velocity_mps).norm() * horizon_s;
    doubtful += d_m - f.radius_m <= reach_m + travel_m + g_m + vc_m ? 1 : 0;
  }
  return doubtful;
}

// Times the strategy it wraps, step by step, and runs the floor pass after it; times the shadow,
// if any, on the same states.
class TimedStrategy final : public fragsim::SceneStrategy {
 public:
  // With `parallel`, its steps (and the shadow's) get it and are timed by the wall clock.
  TimedStrategy(std::unique_ptr<fragsim::SceneStrategy> inner,
                std::unique_ptr<fragsim::SceneStrategy> shadow,
                const fragsim::ParallelFor* parallel)
      : inner_(std::move(inner)), shadow_(std::move(shadow)), parallel_(parallel) {
    if (parallel_ != nullptr) {
      tell_workers(*inner_);
      if (shadow_) tell_workers(*shadow_);
    }
  }
  std::string name() const override { return inner_->name(); }
  fragsim::WorldNeeds needs() const override { return inner_->needs(); }
  fragsim::Predictor path_predictor() const override { return inner_->path_predictor(); }
  void reset(int fragment_count) override {
    inner_->reset(fragment_count);
    // Room for one answer per fragment, its pages touched, as a game keeps its output buffer: the
    // strategy's faults are then its own.
    const auto n = static_cast<std::size_t>(std::max(fragment_count, 0));
    for (fragsim::SceneStepOutput* o : {&own_, &shadow_out_}) {
      fragsim::reserve_touched(o->forces, n);
      fragsim::reserve_touched(o->activity.candidates, n);
      fragsim::reserve_touched(o->activity.capped, n);
    }
    if (shadow_) shadow_->reset(fragment_count);
    times.clear();
    times.reserve(4096);
  }
  void step(const fragsim::StepContext& run_ctx, fragsim::SceneStepOutput& out) override {
    fragsim::StepContext ctx = run_ctx;
    ctx.parallel = parallel_;
    own_.clear();
    StepTimes t;
    const bool shadow_first = times.size() % 2 == 1;
    if (shadow_first) t.shadow_ns = shadow_step(ctx);
    const long faults_before = minor_faults();
    allocations.store(0);
    counting.store(true);
    const double start = now_ns();
    inner_->step(ctx, own_);
    const double stop = now_ns();
    counting.store(false);
    t.faults = minor_faults() - faults_before;
    t.allocations = allocations.load();
    t.strategy_ns = stop - start;
    t.survivors = static_cast<int>(ctx.fragments.size()) - own_.activity.rejected_cheaply;
    t.candidates = static_cast<int>(own_.activity.candidates.size());
    if (!shadow_first) t.shadow_ns = shadow_step(ctx);
    // The floor: a reach of a few metres and a 3 s horizon, the default scene's scale; the count
    // is kept so the pass is not optimised away.
    const double floor_start = thread_cpu_ns();
    sink_ += floor_pass(ctx, 2.0, 3.0);
    t.floor_ns = thread_cpu_ns() - floor_start;
    times.push_back(t);
    out.forces.assign(own_.forces.begin(), own_.forces.end());
    out.near_m = own_.near_m;
    out.opacity.assign(own_.opacity.begin(), own_.opacity.end());
    out.activity.candidates.assign(own_.activity.candidates.begin(),
                                   own_.activity.candidates.end());
    out.activity.capped.assign(own_.activity.capped.begin(), own_.activity.capped.end());
    out.activity.guarded = own_.activity.guarded;
    out.activity.deferred = own_.activity.deferred;
    out.activity.rejected_cheaply = own_.activity.rejected_cheaply;
  }
  std::vector<StepTimes> times;
  long sink() const { return sink_; }

 private:
  double shadow_step(const fragsim::StepContext& ctx) {
    if (!shadow_) return 0.0;
    shadow_out_.clear();
    const double start = now_ns();
    shadow_->step(ctx, shadow_out_);
    return now_ns() - start;
  }
  // The strategy's clock: the calling thread's CPU time, or the wall clock when it has workers.
  double now_ns() const { return parallel_ != nullptr ? wall_ns() : thread_cpu_ns(); }
  // Only the library's strategies take workers; the tool's baselines run as they are.
  void tell_workers(fragsim::SceneStrategy& s) const {
    if (auto* library = dynamic_cast<fragsim::LibraryStrategy*>(&s)) {
      library->inner().set_worker_count(parallel_->worker_count());
    }
  }

  std::unique_ptr<fragsim::SceneStrategy> inner_;
  std::unique_ptr<fragsim::SceneStrategy> shadow_;
  const fragsim::ParallelFor* parallel_;
  fragsim::SceneStepOutput own_;
  fragsim::SceneStepOutput shadow_out_;
  long sink_ = 0;
};

double quantile(std::vector<double> v, double share) {
  if (v.empty()) return std::nan("");
  std::sort(v.begin(), v.end());
  const auto rank = static_cast<std::size_t>(std::ceil(share * static_cast<double>(v.size())));
  return v[std::clamp<std::size_t>(rank, 1, v.size()) - 1];
}

double mean(const std::vector<double>& v) {
  if (v.empty()) return std::nan("");
  double s = 0.0;
  for (const double x : v) s += x;
  return s / static_cast<double>(v.size());
}

// One repeat's figures, each a number so the median over repeats is taken figure by figure.
struct Figures {
  std::vector<double> values;
};

const std::vector<std::string> kNames = {"t0_ns",
                                         "early_mean_ns",
                                         "early_p95_ns",
                                         "lens_mean_ns",
                                         "lens_p95_ns",
                                         "landed_mean_ns",
                                         "landed_p95_ns",
                                         "flight_mean_ns",
                                         "flight_p95_ns",
                                         "run_mean_ns",
                                         "median_step_ns",
                                         "worst_step_ns",
                                         "worst_step",
                                         "floor_flight_ns",
                                         "floor_landed_ns",
                                         "physics_mean_ns",
                                         "share_of_physics",
                                         "first_run_allocations_in_steps",
                                         "first_run_faults_step0",
                                         "first_run_faults_in_steps"};
// With --shadow: its cost, and the strategy's beyond it step by step (the strategy's time less the
// shadow's in the same step), over the flight and the lens pass.
const std::vector<std::string> kShadowNames = {
    "shadow_flight_mean_ns",      "shadow_flight_p95_ns",         "shadow_lens_mean_ns",
    "shadow_lens_p95_ns",         "beyond_shadow_flight_mean_ns", "beyond_shadow_flight_p95_ns",
    "beyond_shadow_lens_mean_ns", "beyond_shadow_lens_p95_ns"};
// With --workers: the strategy's wall time per step (not per fragment), in microseconds.
const std::vector<std::string> kWorkerNames = {"flight_mean_step_us", "flight_p95_step_us",
                                               "lens_mean_step_us", "lens_p95_step_us"};

int run(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr,
                 "usage: worst_frame SCENE STRATEGY [REPEATS] [--workers N] "
                 "[section.key=value ...] [--shadow section.key=value ...]\n");
    return 2;
  }
  const std::string scene_path = argv[1];
  const std::string strategy = argv[2];
  int repeats = 5;
  int first_override = 3;
  if (argc > 3 && std::string(argv[3]).find('=') == std::string::npos) {
    repeats = std::stoi(argv[3]);
    first_override = 4;
  }
  if (repeats < 1) throw std::invalid_argument("REPEATS must be at least 1");
  // The run's settings, then (after --shadow) the shadow's on top of them.
  std::vector<fragsim::SceneOverride> overrides;
  std::vector<fragsim::SceneOverride> shadow_overrides;
  bool in_shadow = false;
  int workers = 0;  // 0: no ParallelFor, the calling thread's CPU time
  for (int i = first_override; i < argc; ++i) {
    const std::string kv = argv[i];
    if (kv == "--workers") {
      if (i + 1 >= argc) throw std::invalid_argument("--workers needs a number");
      workers = std::stoi(argv[++i]);
      if (workers < 1) throw std::invalid_argument("--workers must be at least 1");
      continue;
    }
    if (kv == "--shadow") {
      in_shadow = true;
      continue;
    }
    const auto eq = kv.find('=');
    if (eq == std::string::npos) throw std::invalid_argument("expected key=value, got " + kv);
    (in_shadow ? shadow_overrides : overrides).push_back({kv.substr(0, eq), kv.substr(eq + 1)});
  }
  if (in_shadow && shadow_overrides.empty()) {
    throw std::invalid_argument("--shadow needs at least one key=value");
  }
  const bool shadowed = !shadow_overrides.empty();
  const fragsim::Scene scene = fragsim::load_scene(scene_path, overrides);
  fragsim::validate_strategy_settings(strategy, scene);
  std::vector<fragsim::SceneOverride> both = overrides;
  both.insert(both.end(), shadow_overrides.begin(), shadow_overrides.end());
  const fragsim::Scene shadow_scene = shadowed ? fragsim::load_scene(scene_path, both) : scene;
  if (shadowed) fragsim::validate_strategy_settings(strategy, shadow_scene);

  // Started once, before the runs, as a game's task system is.
  const std::unique_ptr<ThreadPoolFor> pool =
      workers > 0 ? std::make_unique<ThreadPoolFor>(workers) : nullptr;
  std::vector<Figures> all;
  int fragments = 0;
  int steps = 0;
  std::vector<StepTimes> last;
  std::vector<double> last_physics;
  for (int r = 0; r < repeats; ++r) {
    TimedStrategy timed(fragsim::make_strategy(strategy, scene),
                        shadowed ? fragsim::make_strategy(strategy, shadow_scene) : nullptr,
                        pool.get());
    fragsim::Run run(scene, timed);
    fragments = static_cast<int>(run.state().fragments.size());
    std::vector<double> physics_ns;
    while (!run.done()) {
      const std::size_t before = timed.times.size();
      const double start = thread_cpu_ns();
      run.step();
      const double total = thread_cpu_ns() - start;
      // The step less the strategy, its shadow and the floor inside it: the physics and the run's
      // copies.
      const StepTimes& t = timed.times[before];
      physics_ns.push_back(total - t.strategy_ns - t.shadow_ns - t.floor_ns);
    }
    run.finish();
    steps = static_cast<int>(timed.times.size());
    const double n = std::max(fragments, 1);
    std::vector<double> per, floor_per, shadow_per, beyond_per;
    for (const StepTimes& t : timed.times) {
      per.push_back(t.strategy_ns / n);
      floor_per.push_back(t.floor_ns / n);
      shadow_per.push_back(t.shadow_ns / n);
      beyond_per.push_back((t.strategy_ns - t.shadow_ns) / n);
    }
    const auto slice = [](const std::vector<double>& v, int a, int b) {
      a = std::clamp(a, 0, static_cast<int>(v.size()));
      b = std::clamp(b, a, static_cast<int>(v.size()));
      return std::vector<double>(v.begin() + a, v.begin() + b);
    };
    const int landed_from = std::max(60, steps - 60);
    const std::vector<double> early = slice(per, 1, 30);
    const std::vector<double> lens = slice(per, 30, 60);
    const std::vector<double> landed = slice(per, landed_from, steps);
    const std::vector<double> flight = slice(per, 1, 60);
    const auto worst = std::max_element(per.begin(), per.end());
    double strategy_total = 0.0, physics_total = 0.0;
    long allocs = 0, faults = 0;
    for (std::size_t k = 0; k < timed.times.size(); ++k) {
      strategy_total += timed.times[k].strategy_ns;
      physics_total += physics_ns[k];
      allocs += timed.times[k].allocations;
      faults += timed.times[k].faults;
    }
    Figures f;
    f.values = {per.empty() ? std::nan("") : per[0],
                mean(early),
                quantile(early, 0.95),
                mean(lens),
                quantile(lens, 0.95),
                mean(landed),
                quantile(landed, 0.95),
                mean(flight),
                quantile(flight, 0.95),
                mean(per),
                quantile(per, 0.5),
                *worst,
                static_cast<double>(worst - per.begin()),
                mean(slice(floor_per, 1, 60)),
                mean(slice(floor_per, landed_from, steps)),
                mean(physics_ns) / n,
                physics_total > 0.0 ? strategy_total / physics_total : std::nan(""),
                static_cast<double>(allocs),
                timed.times.empty() ? 0.0 : static_cast<double>(timed.times[0].faults),
                static_cast<double>(faults)};
    // Allocations and page faults as a game's first explosion meets them: the first run in the
    // process (later runs reuse the heap the first one grew, so their medians read 0).
    if (!all.empty()) {
      for (std::size_t k = kNames.size() - 3; k < kNames.size(); ++k) {
        f.values[k] = all.front().values[k];
      }
    }
    if (shadowed) {
      for (const std::vector<double>* v : {&shadow_per, &beyond_per}) {
        const std::vector<double> v_flight = slice(*v, 1, 60);
        const std::vector<double> v_lens = slice(*v, 30, 60);
        f.values.insert(f.values.end(), {mean(v_flight), quantile(v_flight, 0.95), mean(v_lens),
                                         quantile(v_lens, 0.95)});
      }
    }
    if (pool) {
      std::vector<double> step_us;
      for (const StepTimes& t : timed.times) step_us.push_back(t.strategy_ns / 1e3);
      const std::vector<double> flight_us = slice(step_us, 1, 60);
      const std::vector<double> lens_us = slice(step_us, 30, 60);
      f.values.insert(f.values.end(), {mean(flight_us), quantile(flight_us, 0.95), mean(lens_us),
                                       quantile(lens_us, 0.95)});
    }
    all.push_back(f);
    last = timed.times;
    last_physics = physics_ns;
    if (timed.sink() < 0) std::printf("\n");  // keeps the floor's count alive
  }
  std::printf("# worst_frame %s %s: %d fragments, %d steps, median of %d runs; ns per fragment\n",
              scene_path.c_str(), strategy.c_str(), fragments, steps, repeats);
  if (pool) {
    std::printf("# %d workers: the strategy's times are wall-clock times\n", workers);
  }
  std::vector<std::string> names = kNames;
  if (shadowed) names.insert(names.end(), kShadowNames.begin(), kShadowNames.end());
  if (pool) names.insert(names.end(), kWorkerNames.begin(), kWorkerNames.end());
  for (std::size_t k = 0; k < names.size(); ++k) {
    std::vector<double> v;
    for (const Figures& f : all) v.push_back(f.values[k]);
    std::printf("%-32s %12.4g\n", names[k].c_str(), quantile(v, 0.5));
  }
  if (const char* file = std::getenv("FRAGSIM_WORST_FRAME_CSV")) {
    std::string text =
        "step,strategy_ns,floor_ns,physics_ns,allocations,faults,survivors,candidates";
    text += shadowed ? ",shadow_ns\n" : "\n";
    const double n = std::max(fragments, 1);
    char line[256];
    for (std::size_t k = 0; k < last.size(); ++k) {
      std::snprintf(line, sizeof line, "%zu,%.3f,%.3f,%.3f,%ld,%ld,%d,%d", k,
                    last[k].strategy_ns / n, last[k].floor_ns / n, last_physics[k] / n,
                    last[k].allocations, last[k].faults, last[k].survivors, last[k].candidates);
      text += line;
      if (shadowed) {
        std::snprintf(line, sizeof line, ",%.3f", last[k].shadow_ns / n);
        text += line;
      }
      text += '\n';
    }
    fragsim::write_file_atomically(file, text);
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "worst_frame: %s\n", e.what());
    return 2;
  }
}
