#include "control/strategies/deflect_all_strategy.hpp"

#include <algorithm>
#include <cstdint>

#include "control/geometry/vec3_sums.hpp"
#include "control/strategies/force_cap.hpp"
#include "control/strategies/parallel_ranges.hpp"

namespace fragsim {
namespace {

// The fewest fragments a worker takes at once. Each is a few dozen operations, so a much shorter
// range would cost more to hand to a worker than to run.
constexpr std::int32_t kMinRange = 1024;

}  // namespace

// Kept at its largest size, its pages written once, as reserve() runs before every step of the
// controller library, where a fresh reserve_touched of the whole array would cost a pass over it.
void DeflectAllStrategy::reserve(int fragment_count) {
  const auto n = static_cast<std::size_t>(std::max(fragment_count, 0));
  if (pushes_.size() < n) pushes_.resize(n);
}

DeflectAllStrategy::Push DeflectAllStrategy::push_of(const StepContext& ctx, std::size_t i) const {
  const CameraPose& cam = ctx.camera;
  const FragmentState& f = ctx.fragments[i];
  const Eigen::Vector3d rel = f.position_m - cam.eye_m;
  if (squared_norm3(rel) > params_.range_m * params_.range_m) return {};
  const Eigen::Vector3d rel_v = f.velocity_mps - ctx.camera_velocity_mps;
  if (dot3(rel, rel_v) >= 0.0) return {};  // not approaching
  // Away from the view axis is along the fragment's offset across the view direction.
  Eigen::Vector3d away = rel - dot3(rel, cam.forward) * cam.forward;
  const double n = norm3(away);
  // A fragment on the axis itself has no "away", so it goes up, as debris usually clears upward.
  away = n > 1e-9 ? Eigen::Vector3d(away / n) : cam.up;
  return {true, f.mass_kg * params_.accel_mps2 * away};
}

void DeflectAllStrategy::step(const StepContext& ctx, StepOutput& out) {
  const std::size_t n = ctx.fragments.size();
  const double accel = params_.accel_mps2;
  const auto apply = [&](std::size_t i, const Push& push) {
    if (push.any) {
      apply_capped(out, static_cast<int>(i), push.force_N, ctx.fragments[i].mass_kg, accel);
    }
  };
  if (ctx.parallel == nullptr) {
    for (std::size_t i = 0; i < n; ++i) apply(i, push_of(ctx, i));
    return;
  }
  if (pushes_.size() < n) pushes_.resize(n);
  const auto push_range = [&](std::int32_t begin, std::int32_t end, std::uint32_t) {
    for (auto i = static_cast<std::size_t>(begin); i < static_cast<std::size_t>(end); ++i) {
      pushes_[i] = push_of(ctx, i);
    }
  };
  for_ranges(ctx.parallel, static_cast<std::int32_t>(n), kMinRange, push_range);
  for (std::size_t i = 0; i < n; ++i) apply(i, pushes_[i]);
}

}  // namespace fragsim
