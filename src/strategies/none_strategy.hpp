#pragma once
// `none`: no control. The reference run against which deviation is measured.

#include "strategies/scene_strategy.hpp"

namespace fragsim {

class NoneStrategy final : public SceneStrategy {
 public:
  std::string name() const override { return "none"; }
  void reset(int) override {}
  void step(const StepContext&, SceneStepOutput&) override {}
};

}  // namespace fragsim
