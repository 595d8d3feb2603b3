#pragma once
// `edge-min`'s parameters (METHOD.md section 4) and their scene keys ([edge-min]).

#include "strategies/param_spec.hpp"

namespace fragsim {

// What edge-min assumes the camera does before a fragment arrives.
enum class CameraModel {
  kConstant,      // keeps its present velocity and orientation (the first edge-min)
  kBoundedAccel,  // may change velocity at up to an acceleration bound and turn at a bounded rate
  kReachable,     // anywhere within V_c t of where it is (the thesis's ball): any acceleration
};

// The least constant push that takes a fragment just past the nearest edge of the protected
// rectangle before it arrives. No gain to tune.
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

const ParamSpec<EdgeMinParams>& edge_min_param_spec();

}  // namespace fragsim
