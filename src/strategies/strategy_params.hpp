#pragma once
// Parameters of each strategy, one plain struct per strategy with defaults and units. They are
// filled from the scene file's section of the same name ([edge], [wall], ...) and are const for
// the length of a run.

#include <string>

namespace fragsim {

// Which ballistic path the prediction uses.
enum class Predictor {
  kThesis,    // (3.1) with the velocity read from the physics.
  kDiscrete,  // ODE's semi-implicit Euler: the parabola with velocity V + g dt/2.
};
// Which region the camera can reach before the fragment lands.
enum class Reach {
  kThesis,   // The fixed ball |X - P_c(t_now)| = V_c (t_G - t_now), plus both radii.
  kGrowing,  // The ball V_c (t - t_now) + radii that grows with time.
};
// Height at which the fragment is taken to "reach the ground" (t_G).
enum class Horizon { kCamera, kGround };
// Which non-candidates are examined again after t = 0.
enum class Replan { kNever, kContact, kAlways };

struct NoneParams {};

struct WallParams {
  double distance_m = 0.6;    // from the eye along the view direction
  double thickness_m = 0.05;  // depth of the box
  double margin = 1.25;       // wall size over the frustum's cross-section at distance_m
  double restitution = 0.3;   // bounce of fragments off the wall
};

struct DeflectAllParams {
  double accel_mps2 = 60.0;  // push away from the view axis, per unit mass
  double range_m = 6.0;      // only fragments closer than this to the eye are pushed
};

struct NearPlaneParams {
  double min_near_m = 0.01;      // the near plane never comes closer than this
  double margin_m = 0.02;        // kept between the near plane and the nearest fragment
  int depth_bits = 24;           // depth buffer precision, for the depth-step report
  double ref_distance_m = 10.0;  // distance at which the depth step is reported
};

struct EdgeParams {
  double k = 1.0;            // gain of (3.4), N m s^2
  double a_max_mps2 = 50.0;  // cap on the imposed acceleration (5 g)
  Predictor predictor = Predictor::kThesis;
  Reach reach = Reach::kThesis;
  Horizon horizon = Horizon::kCamera;
  Replan replan = Replan::kNever;
  // t_G's fallback and cap: a path that never falls through the horizon height is examined this
  // far ahead (the thesis used the scene's end; a game has none, so this is a setting).
  double horizon_cap_s = 3.0;
};

// `edge-min` (METHOD.md section 4): the least constant push that takes a fragment just past the
// nearest edge of the protected rectangle before it arrives. No gain to tune.
// What edge-min assumes the camera does before a fragment arrives.
enum class CameraModel {
  kConstant,      // keeps its present velocity and orientation (the first edge-min)
  kBoundedAccel,  // may change velocity at up to an acceleration bound and turn at a bounded rate
  kReachable,     // anywhere within V_c t of where it is (the thesis's ball): any acceleration
};

struct EdgeMinParams {
  double margin_m = 0.05;    // clearance kept beyond the rectangle's edge
  double a_max_mps2 = 50.0;  // cap on the imposed acceleration (5 g)
  CameraModel camera_model = CameraModel::kBoundedAccel;
  // The bounds assumed when the scene declares none (camera.mode = path or track); a scene that
  // declares its bounds (camera.mode = player) is taken at its word.
  double camera_accel_mps2 = 20.0;
  double camera_turn_degps = 90.0;
  // How far ahead a path is examined: until the fragment reaches the ground (its centre at the
  // ground height plus its radius, going down: the ballistic path means nothing after it
  // bounces), never beyond this cap (a path that never comes down: gravity off, no ground).
  double horizon_cap_s = 3.0;
  // Per-step budget: at most this many fragments that survive the cheap rejection are solved
  // exactly in one step, the most urgent first (time to arrival, distance over closing speed);
  // the rest keep the force of the last step they were solved. 0: no cap.
  int max_solves = 0;
};

}  // namespace fragsim
