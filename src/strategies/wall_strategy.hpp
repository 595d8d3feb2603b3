#pragma once
// `wall` is a transparent kinematic box carried in front of the camera that fragments bounce off
// (thesis fig. 2.1). The strategy itself applies no force; the wall lives in the physics world.

#include "strategies/scene_strategy.hpp"
#include "strategies/wall_params.hpp"

namespace fragsim {

class WallStrategy final : public SceneStrategy {
 public:
  // Sized to the camera's frustum (vertical field of view, aspect).
  WallStrategy(const WallParams& params, double fovy_deg, double aspect);
  std::string name() const override { return "wall"; }
  WorldNeeds needs() const override;
  void reset(int) override {}
  void step(const StepContext&, SceneStepOutput&) override {}

 private:
  CameraWallSpec spec_;
};

}  // namespace fragsim
