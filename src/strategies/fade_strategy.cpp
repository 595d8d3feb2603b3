#include "strategies/fade_strategy.hpp"

#include <algorithm>
#include <cmath>

namespace fragsim {

double box_distance_m(const Eigen::Vector3d& eye_m, const FragmentState& f) {
  // In the box's own axes the nearest point is the eye clamped to the box.
  const Eigen::Vector3d local = f.rotation.transpose() * (eye_m - f.position_m);
  const Eigen::Vector3d nearest = local.cwiseMax(-f.half_extents_m).cwiseMin(f.half_extents_m);
  return (local - nearest).norm();
}

float fade_opacity(const FadeParams& p, double distance_m) {
  const double a = (distance_m - p.end_m) / (p.start_m - p.end_m);
  // A non-finite distance (a state the simulation reports itself) draws nothing.
  if (!std::isfinite(a)) return 0.0f;
  return static_cast<float>(std::clamp(a, 0.0, 1.0));
}

void FadeStrategy::step(const StepContext& ctx, SceneStepOutput& out) {
  // The opacity is the next frame's, the one the state after this step is drawn with, so fragments
  // and camera moved on as the physics will move them (semi-implicit Euler, no force, the
  // rotation kept), as near-plane chooses its near distance. Only contacts make it differ.
  const Eigen::Vector3d eye = ctx.camera.eye_m + ctx.camera_velocity_mps * ctx.dt_s;
  out.opacity.resize(ctx.fragments.size());
  for (std::size_t i = 0; i < ctx.fragments.size(); ++i) {
    FragmentState next = ctx.fragments[i];
    next.velocity_mps += ctx.gravity_mps2 * ctx.dt_s;
    next.position_m += next.velocity_mps * ctx.dt_s;
    out.opacity[i] = fade_opacity(params_, box_distance_m(eye, next));
  }
}

}  // namespace fragsim
