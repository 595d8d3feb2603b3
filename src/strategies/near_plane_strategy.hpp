#pragma once
// `near-plane`: leaves the physics alone and pulls the near plane toward the eye, down to a
// minimum, so that approaching fragments are not cut (thesis fig. 2.6). The cost is depth
// precision, reported as the depth step z^2 / (n 2^b) at a reference distance.

#include "strategies/near_plane_params.hpp"
#include "strategies/strategy.hpp"

namespace fragsim {

class NearPlaneStrategy final : public Strategy {
 public:
  explicit NearPlaneStrategy(const NearPlaneParams& params) : params_(params) {}
  std::string name() const override { return "near-plane"; }
  void reset(int) override {}
  void step(const StepContext& ctx, StepOutput& out) override;

  // The smallest depth difference a depth buffer of `bits` resolves at distance z_m with the near
  // plane at near_m.
  static double depth_step_m(double z_m, double near_m, int bits);

 private:
  NearPlaneParams params_;
};

}  // namespace fragsim
