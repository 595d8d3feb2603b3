#include "strategies/deflect_all_strategy.hpp"

#include "strategies/force_cap.hpp"

namespace fragsim {

void DeflectAllStrategy::step(const StepContext& ctx, StepOutput& out) {
  const CameraPose& cam = ctx.camera;
  const double range2 = params_.range_m * params_.range_m;
  for (std::size_t i = 0; i < ctx.fragments.size(); ++i) {
    const FragmentState& f = ctx.fragments[i];
    const Eigen::Vector3d rel = f.position_m - cam.eye_m;
    if (rel.squaredNorm() > range2) continue;
    const Eigen::Vector3d rel_v = f.velocity_mps - ctx.camera_velocity_mps;
    if (rel.dot(rel_v) >= 0.0) continue;  // not approaching
    // Away from the view axis: the fragment's offset across the view direction.
    Eigen::Vector3d away = rel - rel.dot(cam.forward) * cam.forward;
    const double n = away.norm();
    // A fragment on the axis itself has no "away": push it up, as debris usually clears upward.
    away = n > 1e-9 ? Eigen::Vector3d(away / n) : cam.up;
    const double accel = params_.accel_mps2;
    apply_capped(out, static_cast<int>(i), f.mass_kg * accel * away, f.mass_kg, accel);
  }
}

}  // namespace fragsim
