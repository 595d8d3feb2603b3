#pragma once
// `edge-min`: the minimal force of METHOD.md section 4, generalised from the near plane to the
// whole camera. Every step, every fragment's ballistic path relative to the camera (moving at its
// current velocity) is tested against the protected box: the camera body and the near rectangle
// (whichever is larger on each axis) grown by the fragment's bounding radius and a margin. A
// fragment whose path enters it gets, toward one of the four screen edges (+-right, +-up), the
// least constant acceleration that makes the pushed path miss the box; of the four, the smallest
// wins. Re-solved every step, the push fades to zero once the fragment is clear: distant threats
// get almost nothing, close ones what they need, capped by a_max (the report counts the capped
// fragments that still hit).
//
// Why a box and not only the near plane: a fragment steered just past the near rectangle's edge
// still hits a camera body wider than that rectangle, and debris falling onto the camera from
// above never crosses the near plane at all.

#include "strategies/cheap_rejection.hpp"
#include "strategies/strategy.hpp"
#include "strategies/strategy_params.hpp"

namespace fragsim {

class EdgeMinStrategy final : public Strategy {
 public:
  explicit EdgeMinStrategy(const EdgeMinParams& params) : params_(params) {}
  std::string name() const override { return "edge-min"; }
  void reset(int) override {}
  void step(const StepContext& ctx, StepOutput& out) override;

  // How far a constant acceleration of 1 m/s^2, applied from the coming step on, has moved a body
  // after tau_s under ODE's semi-implicit Euler with step dt_s: sum over n = tau/dt steps of
  // dt * k dt = (tau^2 + tau dt) / 2.
  static double displacement_per_accel(double tau_s, double dt_s) {
    return 0.5 * (tau_s * tau_s + tau_s * dt_s);
  }

 private:
  EdgeMinParams params_;
  BoxClearance clearance_;  // work space kept between steps; holds no state of the run
};

}  // namespace fragsim
