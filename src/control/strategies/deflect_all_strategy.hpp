#pragma once
// `deflect-all`: every fragment approaching the camera within range is pushed away from the view
// axis, with no prediction and no choice of edge (thesis fig. 2.2).

#include <memory_resource>

#include "strategies/deflect_all_params.hpp"
#include "strategies/strategy.hpp"

namespace fragsim {

class DeflectAllStrategy final : public Strategy {
 public:
  // It keeps nothing between steps: `mem` is taken for a constructor like the other strategies'.
  explicit DeflectAllStrategy(const DeflectAllParams& params,
                              std::pmr::memory_resource* mem = std::pmr::get_default_resource())
      : params_(params) {
    (void)mem;
  }
  std::string name() const override { return "deflect-all"; }
  void reset(int) override {}
  void step(const StepContext& ctx, StepOutput& out) override;

 private:
  DeflectAllParams params_;
};

}  // namespace fragsim
