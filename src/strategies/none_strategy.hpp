#pragma once
// `none`: no control. The reference run against which deviation is measured.

#include "strategies/strategy.hpp"

namespace fragsim {

class NoneStrategy final : public Strategy {
 public:
  std::string name() const override { return "none"; }
  void reset(int) override {}
  void step(const StepContext&, StepOutput&) override {}
};

}  // namespace fragsim
