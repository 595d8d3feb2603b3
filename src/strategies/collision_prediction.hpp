#pragma once
// The thesis's collision prediction (section 3.2 of the thesis, METHOD.md section 3): the
// fragment's ballistic path against the ball the camera can reach before the fragment lands.

#include <Eigen/Core>
#include <optional>

#include "sim/camera_pose.hpp"
#include "sim/fragment_state.hpp"
#include "strategies/first_root.hpp"
#include "strategies/strategy_params.hpp"

namespace fragsim {

// P(tau) = p0 + v0 tau + g tau^2 / 2, tau measured from now.
struct BallisticPath {
  Eigen::Vector3d p0_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d v0_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d g_mps2 = Eigen::Vector3d::Zero();

  Eigen::Vector3d at(double tau_s) const {
    return p0_m + v0_mps * tau_s + 0.5 * g_mps2 * tau_s * tau_s;
  }
};

// The path the predictor believes in. `discrete` uses V + g dt/2: ODE's semi-implicit Euler puts
// positions at step times exactly on that parabola.
BallisticPath predicted_path(const FragmentState& f, const Eigen::Vector3d& g_mps2, Predictor p,
                             double dt_s);

// t_G - now: the later time at which the path comes down through height y_ref_m, or `fallback_s`
// when it never does.
double time_to_horizon(const BallisticPath& path, double y_ref_m, double fallback_s);

// |path(tau) - centre|^2 - (r0 + growth tau)^2 as a quartic in tau.
Quartic ball_contact_quartic(const BallisticPath& path, const Eigen::Vector3d& centre_m,
                             double r0_m, double growth_mps);

struct ContactPrediction {
  bool candidate = false;
  double t_contact_s = 0.0;  // tau of the first entry (0 when already inside)
  double t_horizon_s = 0.0;  // tau of t_G
};

struct ReachModel {
  Reach reach = Reach::kThesis;
  double max_speed_mps = 0.0;  // V_c
  double radius_m = 0.0;       // camera body plus fragment: the ball never shrinks below this
};

// Whether the path is inside, or enters, the camera's reachable ball within [0, t_horizon].
ContactPrediction predict_contact(const BallisticPath& path, const Eigen::Vector3d& camera_m,
                                  const ReachModel& model, double t_horizon_s);

// Where a path relative to the camera (moving at camera_velocity) first reaches the near plane,
// in near-plane coordinates (x right, y up, metres). Nothing if it never does within horizon_s.
std::optional<Eigen::Vector2d> near_plane_crossing(const BallisticPath& path,
                                                   const CameraPose& camera,
                                                   const Eigen::Vector3d& camera_velocity_mps,
                                                   double horizon_s);

// Unit world direction perpendicular to the near rectangle's edge nearest to `point`, outward.
Eigen::Vector3d nearest_edge_direction(const CameraPose& camera, const Eigen::Vector2d& point);

}  // namespace fragsim
