#pragma once
// `edge`'s parameters (the thesis, docs/method.md section 3) and their legal values (the tool's
// scene keys, [edge], are src/strategies/edge_keys.hpp).

#include "control/strategies/param_range.hpp"
#include "control/strategies/predictor.hpp"

namespace fragsim {

// Which region the camera can reach before the fragment lands.
enum class Reach {
  kThesis,   // The fixed ball |X - P_c(t_now)| = V_c (t_G - t_now), plus both radii.
  kGrowing,  // The ball V_c (t - t_now) + radii that grows with time.
};
// Height at which the fragment is taken to "reach the ground" (t_G).
enum class Horizon { kCamera, kGround };
// Which non-candidates are examined again after t = 0.
enum class Replan { kNever, kContact, kAlways };

struct EdgeParams {
  double k = 1.0;            // gain of (3.4), N m s^2
  double a_max_mps2 = 50.0;  // cap on the imposed acceleration (5 g)
  Predictor predictor = Predictor::kThesis;
  Reach reach = Reach::kThesis;
  Horizon horizon = Horizon::kCamera;
  Replan replan = Replan::kNever;
  // The fallback and cap for t_G. A path that never falls through the horizon height is examined
  // this far ahead (the thesis used the scene's end; a game has none, so this is a setting).
  double horizon_cap_s = 3.0;
};

// Each numeric field's legal values (param_range.hpp), in the struct's order; the enums are
// checked by the C API against its own enums.
inline constexpr ParamRange kEdgeRanges[] = {
    {.name = "k", .field = "edge.k_Nms2", .lo = 0, .hi = 1e12},
    {.name = "a_max_mps2", .field = "edge.a_max_mps2", .lo = 0, .hi = 1e9},
    {.name = "horizon_cap_s", .field = "horizon_cap_s", .lo = 0, .hi = 3600, .lo_open = true},
};

}  // namespace fragsim
