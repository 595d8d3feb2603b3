#include "strategies/collision_prediction.hpp"

#include <algorithm>
#include <cmath>

namespace fragsim {

BallisticPath predicted_path(const FragmentState& f, const Eigen::Vector3d& g_mps2, Predictor p,
                             double dt_s) {
  BallisticPath path{f.position_m, f.velocity_mps, g_mps2};
  if (p == Predictor::kDiscrete) path.v0_mps += 0.5 * dt_s * g_mps2;
  return path;
}

double time_to_horizon(const BallisticPath& path, double y_ref_m, double fallback_s) {
  // y(tau) - y_ref = a tau^2 + b tau + c with a = g_y / 2.
  const double a = 0.5 * path.g_mps2.y();
  const double b = path.v0_mps.y();
  const double c = path.p0_m.y() - y_ref_m;
  double later = -1.0;
  if (a != 0.0) {
    const double disc = b * b - 4.0 * a * c;
    if (disc >= 0.0) {
      // Stable roots: q = -(b + sign(b) sqrt(disc)) / 2, roots q / a and c / q.
      const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
      const double r1 = q / a;
      const double r2 = q != 0.0 ? c / q : r1;
      later = std::max(r1, r2);
    }
  } else if (b != 0.0) {
    later = -c / b;
  }
  // It must come down through y_ref (downward at that time), and not in the past.
  if (later <= 0.0 || !(b + 2.0 * a * later < 0.0)) return fallback_s;
  return later;
}

Quartic ball_contact_quartic(const BallisticPath& path, const Eigen::Vector3d& centre_m,
                             double r0_m, double growth_mps) {
  const Eigen::Vector3d d = path.p0_m - centre_m;
  const Eigen::Vector3d& v = path.v0_mps;
  const Eigen::Vector3d a = 0.5 * path.g_mps2;
  return {d.dot(d) - r0_m * r0_m, 2.0 * d.dot(v) - 2.0 * r0_m * growth_mps,
          v.dot(v) + 2.0 * d.dot(a) - growth_mps * growth_mps, 2.0 * v.dot(a), a.dot(a)};
}

ContactPrediction predict_contact(const BallisticPath& path, const Eigen::Vector3d& camera_m,
                                  const ReachModel& model, double t_horizon_s) {
  ContactPrediction out;
  out.t_horizon_s = t_horizon_s;
  double r0 = model.radius_m;
  double growth = 0.0;
  if (model.reach == Reach::kThesis) {
    r0 += model.max_speed_mps * t_horizon_s;  // R(t_now) = V_c (t_G - t_now), (3.2)
  } else {
    growth = model.max_speed_mps;
  }
  // Cheap rejection before any root solve: the fragment closes on the ball's centre at most at
  // |V| + |g| tau while the ball grows at `growth`, so if even the closest it could get by the
  // horizon stays outside the ball then, no time in between can be inside.
  const double horizon_s = std::max(t_horizon_s, 0.0);
  const double closest_m = (path.p0_m - camera_m).norm() - path.v0_mps.norm() * horizon_s -
                           0.5 * path.g_mps2.norm() * horizon_s * horizon_s;
  if (closest_m > r0 + growth * horizon_s) return out;
  const auto t =
      first_nonpositive(ball_contact_quartic(path, camera_m, r0, growth), 0.0, t_horizon_s);
  if (t) {
    out.candidate = true;
    out.t_contact_s = *t;
  }
  return out;
}

std::optional<Eigen::Vector2d> near_plane_crossing(const BallisticPath& path,
                                                   const CameraPose& camera,
                                                   const Eigen::Vector3d& camera_velocity_mps,
                                                   double horizon_s) {
  const Eigen::Vector3d d = camera.to_camera(path.p0_m);
  const Eigen::Vector3d w = camera.dir_to_camera(path.v0_mps - camera_velocity_mps);
  const Eigen::Vector3d a = 0.5 * camera.dir_to_camera(path.g_mps2);
  if (d.z() <= camera.near_m) return std::nullopt;  // already at or behind the near plane
  // depth(tau) - near <= 0 first happens at the crossing.
  const Quartic depth{d.z() - camera.near_m, w.z(), a.z(), 0.0, 0.0};
  const auto tau = first_nonpositive(depth, 0.0, horizon_s);
  if (!tau) return std::nullopt;
  const double s = *tau;
  return Eigen::Vector2d(d.x() + w.x() * s + a.x() * s * s, d.y() + w.y() * s + a.y() * s * s);
}

Eigen::Vector3d nearest_edge_direction(const CameraPose& camera, const Eigen::Vector2d& point) {
  const double to_side = camera.near_half_width_m() - std::abs(point.x());
  const double to_top_bottom = camera.near_half_height_m() - std::abs(point.y());
  if (to_side < to_top_bottom)
    return point.x() < 0.0 ? Eigen::Vector3d(-camera.right) : camera.right;
  return point.y() < 0.0 ? Eigen::Vector3d(-camera.up) : camera.up;
}

}  // namespace fragsim
