#pragma once
// The thesis's collision prediction (section 3.2 of the thesis, docs/method.md section 3) tests the
// fragment's ballistic path against the ball the camera can reach before the fragment lands.

#include <Eigen/Core>
#include <optional>
#include <span>
#include <vector>

#include "control/geometry/camera_pose.hpp"
#include "control/geometry/first_root.hpp"
#include "control/geometry/fragment_state.hpp"
#include "control/geometry/parabola.hpp"
#include "control/memory/memory_resource.hpp"
#include "control/strategies/ball_clearance.hpp"
#include "control/strategies/edge_params.hpp"

namespace fragsim {

// P(tau) = p0 + v0 tau + g tau^2 / 2, tau measured from now, is the geometry's parabola, whose
// acceleration is gravity here.
using BallisticPath = Parabola;

// The path the predictor believes in. `discrete` uses V + g dt/2, as ODE's semi-implicit Euler puts
// positions at step times exactly on that parabola.
BallisticPath predicted_path(const FragmentState& f, const Eigen::Vector3d& g_mps2, Predictor p,
                             double dt_s);

// t_G - now, the later time at which the path comes down through height y_ref_m, or `fallback_s`
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
  double radius_m = 0.0;       // camera body plus fragment, the ball's least radius
};

// Whether the path is inside, or enters, the camera's reachable ball within [0, t_horizon], by the
// cheap rejection (path_clears_ball), then solve_contact.
ContactPrediction predict_contact(const BallisticPath& path, const Eigen::Vector3d& camera_m,
                                  const ReachModel& model, double t_horizon_s);

// predict_contact without the cheap rejection in front, for paths it left in doubt.
ContactPrediction solve_contact(const BallisticPath& path, const Eigen::Vector3d& camera_m,
                                const ReachModel& model, double t_horizon_s);

// What `edge` asks of each fragment it examines, the path its predictor believes in, t_G (never
// past the look-ahead's cap) and the contact with the ball the camera can reach.
struct ContactQuery {
  Eigen::Vector3d camera_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d gravity_mps2 = Eigen::Vector3d::Zero();
  Predictor predictor = Predictor::kThesis;
  double dt_s = 0.0;
  double y_ref_m = 0.0;      // the height whose downward crossing is t_G
  double remaining_s = 0.0;  // look-ahead left, t_G's fallback and cap
  Reach reach = Reach::kThesis;
  double max_speed_mps = 0.0;  // V_c
  double body_radius_m = 0.0;  // the camera body's; each fragment adds its own

  BallisticPath path(const FragmentState& f) const {
    return predicted_path(f, gravity_mps2, predictor, dt_s);
  }
  double t_horizon_s(const BallisticPath& p) const;
  ReachModel model(const FragmentState& f) const {
    return {reach, max_speed_mps, body_radius_m + f.radius_m};
  }
  // predict_contact(path(f), camera_m, model(f), t_horizon_s(path(f))).
  ContactPrediction predict(const FragmentState& f) const;
};

// ContactQuery::predict for many fragments, with the same answers. The cheap rejection runs first
// over them as batched passes (BallClearance), the solve only on those left in doubt.
class ContactPredictor {
 public:
  explicit ContactPredictor(MemoryResource* mem = default_memory_resource()) : mem_(mem) {}
  // One prediction per index in `which`, in order, valid until the next call. `screen`, when not
  // empty, says per index whether the cheap rejection is worth trying first. It is not for a
  // fragment that was a candidate a step ago and almost surely still is (the answer is the same
  // either way). `guess_s`, when not empty, is per index a guess of the contact time (NaN if none),
  // searched first within guess_half_width_s of it. first_nonpositive_near finds the same contact
  // to the search's accuracy, without the derivative's roots when the guess brackets it.
  std::span<const ContactPrediction> predict(const ContactQuery& query,
                                             std::span<const FragmentState> fragments,
                                             std::span<const int> which,
                                             std::span<const char> screen = {},
                                             std::span<const double> guess_s = {},
                                             double guess_half_width_s = 0.0);
  // Room for predictions of up to n fragments.
  void reserve(std::size_t n);

 private:
  MemoryResource* mem_;
  BallClearance clearance_{mem_};
  ResourceVector<int> screened_{mem_};  // positions in `which` that go through the rejection
  // The screened fragments' path velocity and height, radius and t_G.
  ResourceVector<double> vy_{mem_}, py_{mem_}, radius_{mem_}, t_horizon_{mem_};
  // The quartics left to solve, their horizons and the positions in `which` they answer for.
  ResourceVector<Quartic> quartics_{mem_};
  ResourceVector<double> quartic_horizons_s_{mem_};
  ResourceVector<int> quartic_of_{mem_};
  ResourceVector<double> quartic_guess_s_{mem_};
  FirstNonpositiveBatch roots_{mem_};
  ResourceVector<ContactPrediction> out_{mem_};
};

// Where a path relative to the camera (moving at camera_velocity) first reaches the near plane,
// in near-plane coordinates (x right, y up, metres). Nothing if it never does within horizon_s.
std::optional<Eigen::Vector2d> near_plane_crossing(const BallisticPath& path,
                                                   const CameraPose& camera,
                                                   const Eigen::Vector3d& camera_velocity_mps,
                                                   double horizon_s);

// Unit world direction perpendicular to the near rectangle's edge nearest to `point`, outward.
Eigen::Vector3d nearest_edge_direction(const CameraPose& camera, const Eigen::Vector2d& point);
// The same, with the rectangle's half sizes computed once (camera.near_half_width_m(), ...).
Eigen::Vector3d nearest_edge_direction(const CameraPose& camera, const Eigen::Vector2d& point,
                                       double half_width_m, double half_height_m);

// `edge`'s push direction, nearest_edge_direction at the point near_plane_crossing gives, or at
// `now_m` (the fragment's position) when there is no crossing. It finds the same answer mostly
// without a root search, as the depth is a quadratic, crossed where its closed-form root says. Only
// a case near a decision (a root close to 0, the horizon or a double root, a point close to an axis
// or to the rectangle's diagonals) is handed to near_plane_crossing.
Eigen::Vector3d crossing_edge_direction(const BallisticPath& path, const CameraPose& camera,
                                        const Eigen::Vector3d& camera_velocity_mps,
                                        double horizon_s, const Eigen::Vector3d& now_m,
                                        double half_width_m, double half_height_m);

}  // namespace fragsim
