#pragma once
// `none` applies no control and is the reference run for deviation.

#include "strategies/scene_strategy.hpp"

namespace fragsim {

class NoneStrategy final : public SceneStrategy {
 public:
  std::string name() const override { return "none"; }
  void reset(int) override {}
  void step(const StepContext&, SceneStepOutput&) override {}
};

}  // namespace fragsim
