#pragma once
// `near-plane` leaves the physics alone and pulls the near plane toward the eye, down to a
// minimum, so approaching fragments are not cut (thesis fig. 2.6). The cost is depth
// precision, reported as the depth step at a reference distance (geometry/depth_buffer.hpp).

#include "strategies/near_plane_params.hpp"
#include "strategies/scene_strategy.hpp"

namespace fragsim {

class NearPlaneStrategy final : public SceneStrategy {
 public:
  explicit NearPlaneStrategy(const NearPlaneParams& params) : params_(params) {}
  std::string name() const override { return "near-plane"; }
  void reset(int) override {}
  void step(const StepContext& ctx, SceneStepOutput& out) override;

 private:
  NearPlaneParams params_;
};

}  // namespace fragsim
