// deflect-all with its per-fragment pushes on workers (StepContext::parallel): bit for bit the
// answer of the calling thread alone, for any number of workers and any cut into ranges.
//
// 15,625 fragments (front.ini with object.splits = 25), enough for the strategy's ranges of at
// least 1,024 fragments to be cut several ways, through the tool's run loop: the serial strategy
// drives the run, and copies on 1, 2, 3 and 8 workers whose ranges are uneven and random
// (tests/support/random_ranges_for.hpp) answer on the same context every step.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "control/strategies/deflect_all_strategy.hpp"
#include "sim/simulation.hpp"
#include "strategies/scene_strategy.hpp"
#include "support/random_ranges_for.hpp"
#include "support/shipped_scene.hpp"

namespace fragsim {
namespace {

bool same_bits(const StepOutput& a, const StepOutput& b) {
  if (a.forces.size() != b.forces.size()) return false;
  for (std::size_t k = 0; k < a.forces.size(); ++k) {
    if (a.forces[k].fragment != b.forces[k].fragment) return false;
    if (std::memcmp(a.forces[k].force_N.data(), b.forces[k].force_N.data(), 3 * sizeof(double))) {
      return false;
    }
  }
  return a.activity.capped == b.activity.capped && a.activity.guarded == b.activity.guarded &&
         a.activity.candidates == b.activity.candidates;
}

class Lockstep final : public Strategy {
 public:
  explicit Lockstep(const DeflectAllParams& params) : serial_(params) {
    for (const int workers : {1, 2, 3, 8}) {
      copies_.push_back({std::make_unique<test::RandomRangesFor>(workers, 104729u * workers),
                         std::make_unique<DeflectAllStrategy>(params), StepOutput{}});
      copies_.back().strategy->set_worker_count(workers);
    }
  }
  std::string name() const override { return serial_.name(); }
  void reset(int fragment_count) override {
    serial_.reset(fragment_count);
    for (Copy& c : copies_) c.strategy->reset(fragment_count);
  }
  void step(const StepContext& ctx, StepOutput& out) override {
    serial_.step(ctx, out);
    forces_ += out.forces.size();
    for (Copy& c : copies_) {
      c.out.clear();
      StepContext on_workers = ctx;
      on_workers.parallel = c.parallel.get();
      c.strategy->step(on_workers, c.out);
      if (!same_bits(out, c.out) && first_difference_.empty()) {
        first_difference_ = "step " + std::to_string(ctx.step) + ", " +
                            std::to_string(c.parallel->worker_count()) + " workers";
      }
    }
  }
  const std::string& first_difference() const { return first_difference_; }
  std::size_t forces() const { return forces_; }
  int fewest_split_runs() const {
    int fewest = copies_.front().parallel->split_runs();
    for (const Copy& c : copies_) fewest = std::min(fewest, c.parallel->split_runs());
    return fewest;
  }

 private:
  struct Copy {
    std::unique_ptr<test::RandomRangesFor> parallel;
    std::unique_ptr<DeflectAllStrategy> strategy;
    StepOutput out;
  };
  DeflectAllStrategy serial_;
  std::vector<Copy> copies_;
  std::string first_difference_;
  std::size_t forces_ = 0;
};

TEST(DeflectAllParallel, AnswersAsSerialAt15625Fragments) {
  Scene scene = test::scene_named("front");
  scene.object.splits = 25;
  scene.sim.duration_s = 0.8;  // the debris comes within the 6 m range at about 0.4 s
  LibraryStrategy run_strategy(std::make_unique<Lockstep>(DeflectAllParams{}));
  simulate(scene, run_strategy);
  const auto& lockstep = static_cast<const Lockstep&>(run_strategy.inner());
  EXPECT_EQ(lockstep.first_difference(), "");
  EXPECT_GT(lockstep.forces(), 0u);
  EXPECT_GT(lockstep.fewest_split_runs(), 0);
}

}  // namespace
}  // namespace fragsim
