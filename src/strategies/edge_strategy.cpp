#include "strategies/edge_strategy.hpp"

#include <algorithm>

#include "strategies/force_cap.hpp"

namespace fragsim {

void EdgeStrategy::reset(int fragment_count) {
  // At t = 0 every fragment is examined; afterwards only those still candidates.
  candidate_.assign(static_cast<std::size_t>(fragment_count), 1);
  pushed_.assign(static_cast<std::size_t>(fragment_count), 0);
}

bool EdgeStrategy::should_examine(const StepContext& ctx, std::size_t i) const {
  if (candidate_[i]) return true;
  switch (params_.replan) {
    case Replan::kNever:
      return false;
    case Replan::kContact:
      return ctx.fragments[i].touched || pushed_[i];
    case Replan::kAlways:
      return true;
  }
  return false;
}

void EdgeStrategy::step(const StepContext& ctx, StepOutput& out) {
  const CameraPose& cam = ctx.camera;
  const double body_radius_m = ctx.camera_body_half_m.norm();
  const double y_ref_m = params_.horizon == Horizon::kCamera ? cam.eye_m.y() : ctx.ground_height_m;
  const double remaining_s = std::max(ctx.duration_s - ctx.t_s, 0.0);
  for (std::size_t i = 0; i < ctx.fragments.size(); ++i) {
    if (!should_examine(ctx, i)) continue;
    pushed_[i] = 0;
    const FragmentState& f = ctx.fragments[i];
    const BallisticPath path = predicted_path(f, ctx.gravity_mps2, params_.predictor, ctx.dt_s);
    // Nothing after the scene's end can hit the camera: t_G never reaches past it.
    const double t_ground_s = std::min(time_to_horizon(path, y_ref_m, remaining_s), remaining_s);
    const ReachModel reach{params_.reach, ctx.camera_max_speed_mps, body_radius_m + f.radius_m};
    const ContactPrediction pred = predict_contact(path, cam.eye_m, reach, t_ground_s);
    candidate_[i] = pred.candidate ? 1 : 0;
    if (!pred.candidate) continue;
    out.candidates.push_back(static_cast<int>(i));

    // Direction: toward the near rectangle's edge nearest to where the path will cross it; a
    // path that will not cross (already past, or moving away) is judged where it is now.
    Eigen::Vector2d screen;
    if (auto crossing = near_plane_crossing(path, cam, ctx.camera_velocity_mps, t_ground_s)) {
      screen = *crossing;
    } else {
      const Eigen::Vector3d c = cam.to_camera(f.position_m);
      screen = c.head<2>();
    }
    const Eigen::Vector3d dir = nearest_edge_direction(cam, screen);

    // Magnitude (3.4): k |V_pc| / (|P_pc|^2 (t_C - t)). Both denominators vanish at the camera:
    // they are kept at least one step and one contact distance, and the result is capped.
    const double rel_speed_mps = (f.velocity_mps - ctx.camera_velocity_mps).norm();
    double dist_m = (f.position_m - cam.eye_m).norm();
    double lead_s = pred.t_contact_s;
    if (lead_s < ctx.dt_s || dist_m < reach.radius_m) ++out.guarded;
    lead_s = std::max(lead_s, ctx.dt_s);
    dist_m = std::max(dist_m, reach.radius_m);
    const double force_N = params_.k * rel_speed_mps / (dist_m * dist_m * lead_s);
    const std::size_t before = out.forces.size();
    apply_capped(out, static_cast<int>(i), force_N * dir, f.mass_kg, params_.a_max_mps2);
    pushed_[i] = out.forces.size() > before ? 1 : 0;
  }
}

}  // namespace fragsim
