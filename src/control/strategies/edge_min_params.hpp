#pragma once
// `edge-min`'s parameters (docs/method.md section 4) and their legal values (the tool's scene
// keys, [edge-min], are src/strategies/edge_min_keys.hpp).

#include <array>
#include <limits>

#include "control/strategies/param_range.hpp"

namespace fragsim {

// What edge-min assumes the camera does before a fragment arrives.
enum class CameraModel {
  kConstant,      // keeps its present velocity and orientation
  kBoundedAccel,  // may change velocity at up to an acceleration bound and turn at a bounded rate
  kReachable,     // anywhere within V_c t of where it is (the thesis's ball), at any acceleration
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
  // inf (the default) is no turn bound; each side of the protected box then reaches at once as far
  // as the ball every orientation of it lies in, grown by the translation (docs/camera_models.md).
  double camera_turn_degps = std::numeric_limits<double>::infinity();
  // A path is examined until the fragment reaches the ground (its centre at the ground height plus
  // its radius, going down, as the ballistic path means nothing after it bounces), never beyond
  // this cap (for a path that never comes down, with gravity off or no ground).
  double horizon_cap_s = 3.0;
  // The per-step budget. At most this many fragments that survive the cheap rejection are solved
  // exactly in one step, the most urgent first (time to arrival, distance over closing speed); the
  // rest keep the force of the last step they were solved. 0 means no cap.
  int max_solves = 0;
  // The director's say in the exits (docs/visibility.md, section 2), a weight per screen edge, top,
  // bottom, left, right. Of the ways out a push may take, the one of least push divided by its
  // weight wins, and a weight of 0 forbids that edge. 1 1 1 1 gives the plain least push.
  std::array<double, 4> edge_weights{1.0, 1.0, 1.0, 1.0};
  // The occlusion bound (docs/visibility.md, section 1). The share of the central region (the
  // middle cover_region of the screen's width and height, as metrics.central_share measures it)
  // that debris is predicted to cover at any sampled step within cover_horizon_s may not exceed
  // cover_max; the fragments covering most are pushed out of the region, the least push each, until
  // it does not. 1 turns it off (no prediction at all, the push above alone).
  double cover_max = 1.0;
  double cover_region = 0.5;     // share of the width and height (metrics.central_share)
  double cover_horizon_s = 1.0;  // how far ahead coverage is predicted
  int cover_samples = 12;        // predicted steps per doubling of the lead time
  int cover_cells = 32;          // cells across the region's width; rows follow the aspect
  // How far under the bound the prediction aims, as its discs and coarse cells against the metric's
  // boxes and pixels put the measured maximum up to 2.3 points over an exact aim on front.ini.
  double cover_margin = 0.03;
};

// Each numeric field's legal values (param_range.hpp), in the struct's order; camera_model is
// checked by the C API against its own enum. edge_weights' range is each weight's, and at least one
// must be > 0 (some_edge_allowed). The assumed camera bounds stand in for a camera that declares
// none, so the acceleration must be a number to reason with (a camera that accelerates without
// bound is `reachable`'s case); the turn rate may be inf, as every orientation is bounded by the
// ball around the eye. The cover_* fields past cover_region have no field in the C def.
inline constexpr ParamRange kEdgeMinRanges[] = {
    {.name = "margin_m", .field = "edge_min.margin_m", .lo = 0, .hi = 100},
    {.name = "a_max_mps2", .field = "edge_min.a_max_mps2", .lo = 0, .hi = 1e9},
    {.name = "camera_accel_mps2", .field = "edge_min.camera_accel_mps2", .lo = 0, .hi = 1e6},
    {.name = "camera_turn_degps",
     .field = "edge_min.camera_turn_degps",
     .lo = 0,
     .hi = 1e6,
     .inf_ok = true},
    {.name = "horizon_cap_s", .field = "horizon_cap_s", .lo = 0, .hi = 3600, .lo_open = true},
    {.name = "max_solves", .field = "edge_min.max_solves", .lo = 0, .hi = 1e8, .whole = true},
    {.name = "edge_weights", .field = "edge_min.edge_weights", .lo = 0, .hi = 1e6},
    {.name = "cover_max", .field = "edge_min.cover_max", .lo = 0, .hi = 1},
    {.name = "cover_region", .field = "edge_min.cover_region", .lo = 0, .hi = 1, .lo_open = true},
    {.name = "cover_horizon_s", .field = nullptr, .lo = 0, .hi = 10, .lo_open = true},
    {.name = "cover_samples", .field = nullptr, .lo = 1, .hi = 120, .whole = true},
    {.name = "cover_cells", .field = nullptr, .lo = 2, .hi = 256, .whole = true},
    {.name = "cover_margin", .field = nullptr, .lo = 0, .hi = 0.5},
};

// The edge weights' rule beyond each weight's range, not all four edges forbidden.
constexpr bool some_edge_allowed(const std::array<double, 4>& w) {
  return w[0] > 0.0 || w[1] > 0.0 || w[2] > 0.0 || w[3] > 0.0;
}

}  // namespace fragsim
