// edge-min with its per-fragment work on workers (StepContext::parallel): the cheap rejection in
// chunks and the exact solves in ranges must answer bit for bit what the calling thread alone
// answers, for any number of workers and any cut into ranges.
//
// Each test runs a shipped scene through the tool's run loop with a strategy that steps the
// serial edge-min (whose forces drive the run) and, on the same context, copies of it on 1, 2, 3
// and 8 workers whose ranges are uneven and random (tests/support/random_ranges_for.hpp), and
// compares every step's answer: forces (their bits), candidates, capped, guarded, deferred and
// rejected_cheaply. In some steps a few fragments are given radii above every other's, so that
// the rejection's window, set from the last step's largest radius, is too small and the pass is
// repeated (the robust models).

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "control/strategies/edge_min_strategy.hpp"
#include "sim/simulation.hpp"
#include "strategies/scene_strategy.hpp"
#include "support/random_ranges_for.hpp"
#include "support/shipped_scene.hpp"

namespace fragsim {
namespace {

// The same answer, bit for bit; on a difference, a message naming it.
std::string difference(const StepOutput& serial, const StepOutput& parallel) {
  if (serial.forces.size() != parallel.forces.size()) return "force count";
  for (std::size_t k = 0; k < serial.forces.size(); ++k) {
    const AppliedForce& a = serial.forces[k];
    const AppliedForce& b = parallel.forces[k];
    if (a.fragment != b.fragment) return "force " + std::to_string(k) + "'s fragment";
    if (std::memcmp(a.force_N.data(), b.force_N.data(), 3 * sizeof(double)) != 0) {
      return "force " + std::to_string(k) + "'s bits";
    }
  }
  const StepActivity& x = serial.activity;
  const StepActivity& y = parallel.activity;
  if (x.candidates != y.candidates) return "candidates";
  if (x.capped != y.capped) return "capped";
  if (x.guarded != y.guarded) return "guarded";
  if (x.deferred != y.deferred) return "deferred";
  if (x.rejected_cheaply != y.rejected_cheaply) return "rejected_cheaply";
  return {};
}

// The serial edge-min and its copies on workers, stepped on the same contexts.
class Lockstep final : public Strategy {
 public:
  static constexpr int kWorkers[] = {1, 2, 3, 8};

  Lockstep(const EdgeMinParams& params, bool radii_above_hint) : serial_(params) {
    radii_above_hint_ = radii_above_hint;
    for (const int workers : kWorkers) {
      Copy c;
      c.parallel = std::make_unique<test::RandomRangesFor>(workers, 7919u * workers);
      c.strategy = std::make_unique<EdgeMinStrategy>(params);
      c.strategy->set_worker_count(workers);
      copies_.push_back(std::move(c));
    }
  }

  std::string name() const override { return serial_.name(); }
  void reset(int fragment_count) override {
    serial_.reset(fragment_count);
    for (Copy& c : copies_) c.strategy->reset(fragment_count);
  }
  void step(const StepContext& ctx, StepOutput& out) override {
    StepContext shared = ctx;
    if (radii_above_hint_ && ctx.step % 6 == 3) shared.fragments = with_larger_radii(ctx.fragments);
    serial_.step(shared, out);
    candidates_ += out.activity.candidates.size();
    forces_ += out.forces.size();
    rejected_ += static_cast<std::size_t>(out.activity.rejected_cheaply);
    for (Copy& c : copies_) {
      c.out.clear();
      StepContext on_workers = shared;
      on_workers.parallel = c.parallel.get();
      c.strategy->step(on_workers, c.out);
      const std::string what = difference(out, c.out);
      if (!what.empty() && first_difference_.empty()) {
        first_difference_ = "step " + std::to_string(ctx.step) + ", " +
                            std::to_string(c.parallel->worker_count()) + " workers: " + what;
      }
    }
  }

  // Empty when every copy answered as the serial strategy at every step.
  const std::string& first_difference() const { return first_difference_; }
  // What the run exercised: the serial answers' totals, the steps with radii above the hint, and
  // the fewest run() calls of a copy that cut their items into several ranges.
  std::size_t candidates() const { return candidates_; }
  std::size_t forces() const { return forces_; }
  std::size_t rejected() const { return rejected_; }
  int enlarged_steps() const { return enlarged_steps_; }
  int fewest_split_runs() const {
    int fewest = copies_.front().parallel->split_runs();
    for (const Copy& c : copies_) fewest = std::min(fewest, c.parallel->split_runs());
    return fewest;
  }

 private:
  struct Copy {
    std::unique_ptr<test::RandomRangesFor> parallel;
    std::unique_ptr<EdgeMinStrategy> strategy;
    StepOutput out;
  };

  // The fragments with a few (about one in 300) given radii above the largest of all: the
  // largest radius then exceeds the one the last step left as the rejection's hint.
  std::span<const FragmentState> with_larger_radii(std::span<const FragmentState> fragments) {
    larger_.assign(fragments.begin(), fragments.end());
    double r_max_m = 0.0;
    for (const FragmentState& f : larger_) r_max_m = std::max(r_max_m, f.radius_m);
    for (std::size_t i = 17, j = 0; i < larger_.size(); i += 331, ++j) {
      larger_[i].radius_m = r_max_m * (1.5 + 0.25 * static_cast<double>(j));
    }
    ++enlarged_steps_;
    return larger_;
  }

  EdgeMinStrategy serial_;
  std::vector<Copy> copies_;
  bool radii_above_hint_ = false;
  std::vector<FragmentState> larger_;
  std::string first_difference_;
  std::size_t candidates_ = 0;
  std::size_t forces_ = 0;
  std::size_t rejected_ = 0;
  int enlarged_steps_ = 0;
};

EdgeMinParams with_model(CameraModel model) {
  EdgeMinParams p;
  p.camera_model = model;
  return p;
}

// A scene (front.ini: 1,728 fragments, 180 steps) run in lockstep, and what it exercised.
void expect_same_on_front(const EdgeMinParams& params, Scene scene = test::scene_named("front")) {
  LibraryStrategy run_strategy(std::make_unique<Lockstep>(params, /*radii_above_hint=*/true));
  simulate(scene, run_strategy);
  const auto& lockstep = static_cast<const Lockstep&>(run_strategy.inner());
  EXPECT_EQ(lockstep.first_difference(), "");
  // The run did what is compared: solves that found threats and pushed, a rejection that settled
  // fragments, steps with radii above the hint, and ranges cut several ways.
  EXPECT_GT(lockstep.candidates(), 0u);
  EXPECT_GT(lockstep.forces(), 0u);
  EXPECT_GT(lockstep.rejected(), 0u);
  EXPECT_GT(lockstep.enlarged_steps(), 0);
  EXPECT_GT(lockstep.fewest_split_runs(), 0);
}

TEST(EdgeMinParallel, DefaultModelAnswersAsSerialOnFront) {
  expect_same_on_front(EdgeMinParams{});
}

TEST(EdgeMinParallel, ConstantModelAnswersAsSerialOnFront) {
  expect_same_on_front(with_model(CameraModel::kConstant));
}

TEST(EdgeMinParallel, ReachableModelAnswersAsSerialOnFront) {
  expect_same_on_front(with_model(CameraModel::kReachable));
}

// The budget and the occlusion bound stay on the calling thread, after the parallel rejection.
TEST(EdgeMinParallel, BudgetAndOcclusionBoundAnswerAsSerialOnFront) {
  EdgeMinParams p;
  p.max_solves = 40;
  p.cover_max = 0.3;
  Scene scene = test::scene_named("front");
  scene.sim.duration_s = 1.0;
  expect_same_on_front(p, scene);
}

// 15,625 fragments (object.splits = 25), the flight's first half second: thousands left in doubt
// by the rejection's first tier, over many chunks.
TEST(EdgeMinParallel, DefaultModelAnswersAsSerialAt15625Fragments) {
  Scene scene = test::scene_named("front");
  scene.object.splits = 25;
  scene.sim.duration_s = 0.5;
  expect_same_on_front(EdgeMinParams{}, scene);
}

}  // namespace
}  // namespace fragsim
