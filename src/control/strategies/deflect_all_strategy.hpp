#pragma once
// `deflect-all` pushes every fragment approaching the camera within range away from the view axis,
// with no prediction and no choice of edge (thesis fig. 2.2).

#include <Eigen/Core>
#include <vector>

#include "control/memory/memory_resource.hpp"
#include "control/strategies/deflect_all_params.hpp"
#include "control/strategies/strategy.hpp"

namespace fragsim {

class DeflectAllStrategy final : public Strategy {
 public:
  // It keeps nothing of the run between steps; `mem` holds the parallel step's work space.
  explicit DeflectAllStrategy(const DeflectAllParams& params,
                              MemoryResource* mem = default_memory_resource())
      : params_(params), pushes_(mem) {}
  std::string name() const override { return "deflect-all"; }
  void reset(int fragment_count) override { reserve(fragment_count); }
  void reserve(int fragment_count) override;
  // Each fragment's push is its own, so they run on ctx.parallel's workers, one slot per fragment,
  // gathered in fragment order afterwards (the same forces and capped as on one thread).
  void step(const StepContext& ctx, StepOutput& out) override;

 private:
  // One fragment's push, if it gets one (before the cap, which the gather applies in order).
  struct Push {
    bool any = false;
    Eigen::Vector3d force_N = Eigen::Vector3d::Zero();
  };
  Push push_of(const StepContext& ctx, std::size_t i) const;

  DeflectAllParams params_;
  ResourceVector<Push> pushes_;  // the parallel step's, one per fragment
};

}  // namespace fragsim
