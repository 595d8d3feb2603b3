#pragma once
// `edge`: the thesis's method (docs/method.md section 3). At t = 0 every fragment's ballistic path
// is tested against the ball the camera can reach before the fragment lands; only the fragments
// that pass (the candidates) are examined in later steps, each getting the force (3.4) toward the
// near rectangle's edge nearest to where its path crosses the near plane, until it stops being a
// candidate.

#include <span>
#include <vector>

#include "strategies/collision_prediction.hpp"
#include "strategies/edge_params.hpp"
#include "strategies/strategy.hpp"

namespace fragsim {

class EdgeStrategy final : public Strategy {
 public:
  explicit EdgeStrategy(const EdgeParams& params) : params_(params) {}
  std::string name() const override { return "edge"; }
  Predictor path_predictor() const override { return params_.predictor; }
  void reset(int fragment_count) override;
  void step(const StepContext& ctx, StepOutput& out) override;

  // For a caller whose fragments come and go between steps (the controller library): re-index
  // the run state to the coming step's fragment list. previous[i] is the index fragment i had in
  // the last step, or -1 for a fragment new to the run, which is examined at its first step as
  // every fragment is at t = 0. Fragments absent from `previous` are forgotten. Without this
  // call the fragment list is taken to be the same as at the last step.
  // Within the room reserve() made, it allocates nothing; undo_carry_over() puts back the state
  // of before the last carry_over.
  void carry_over(std::span<const int> previous);
  void undo_carry_over();
  void reserve(int fragment_count) override;

 private:
  bool should_examine(const StepContext& ctx, std::size_t i) const;

  EdgeParams params_;
  std::vector<char> candidate_;  // examined again next step
  std::vector<char> pushed_;     // got a force in the last step
  std::vector<char> predicted_;  // was a candidate by the last prediction (not just by reset)
  // The three above as they were before the last carry_over.
  std::vector<char> candidate_before_, pushed_before_, predicted_before_;
  // Work space, kept between steps to save allocations; holds no state of the run.
  std::vector<int> examined_;
  std::vector<char> screen_;
  ContactPredictor predictor_;
};

}  // namespace fragsim
