#pragma once
// `edge` is the thesis's method (docs/method.md section 3). At t = 0 every fragment's ballistic
// path is tested against the ball the camera can reach before the fragment lands; only the
// fragments that pass (the candidates) are examined in later steps, each getting the force (3.4)
// toward the near rectangle's edge nearest to where its path crosses the near plane, until it stops
// being a candidate.

#include <span>
#include <vector>

#include "control/memory/memory_resource.hpp"
#include "control/strategies/collision_prediction.hpp"
#include "control/strategies/edge_params.hpp"
#include "control/strategies/strategy.hpp"

namespace fragsim {

class EdgeStrategy final : public Strategy {
 public:
  // Its state and work space are allocated from `mem` (the controller library's allocator hook).
  explicit EdgeStrategy(const EdgeParams& params, MemoryResource* mem = default_memory_resource())
      : params_(params), mem_(mem) {}
  std::string name() const override { return "edge"; }
  void reset(int fragment_count) override;
  void step(const StepContext& ctx, StepOutput& out) override;

  // For a caller whose fragments come and go between steps (the controller library), re-indexes the
  // run state to the coming step's fragment list. previous[i] is the index fragment i had in the
  // last step, or -1 for a fragment new to the run, which is examined at its first step as every
  // fragment is at t = 0. Fragments absent from `previous` are forgotten. Without this call the
  // fragment list is taken to be the same as at the last step. Within the room reserve() made, it
  // allocates nothing; undo_carry_over() puts back the state of before the last carry_over.
  void carry_over(std::span<const int> previous);
  void undo_carry_over();
  void reserve(int fragment_count) override;

 private:
  bool should_examine(const StepContext& ctx, std::size_t i) const;

  EdgeParams params_;
  MemoryResource* mem_;
  ResourceVector<char> candidate_{mem_};  // examined again next step
  ResourceVector<char> pushed_{mem_};     // got a force in the last step
  ResourceVector<char> predicted_{mem_};  // was a candidate by the last prediction (not reset's)
  // The contact time the last prediction found (NaN if none), relative to that step. A step later
  // the contact is near it less dt, where its root search starts (first_nonpositive_near).
  ResourceVector<double> last_contact_s_{mem_};
  // The four above as they were before the last carry_over.
  ResourceVector<char> candidate_before_{mem_}, pushed_before_{mem_}, predicted_before_{mem_};
  ResourceVector<double> last_contact_before_s_{mem_};
  // Work space, kept between steps to save allocations; holds no state of the run.
  ResourceVector<int> examined_{mem_};
  ResourceVector<char> screen_{mem_};
  ResourceVector<double> guess_s_{mem_};
  ContactPredictor predictor_{mem_};
};

}  // namespace fragsim
