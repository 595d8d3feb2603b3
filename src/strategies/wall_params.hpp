#pragma once
// `wall`'s parameters and their scene keys ([wall]).

#include "strategies/param_spec.hpp"

namespace fragsim {

struct WallParams {
  double distance_m = 0.6;    // from the eye along the view direction
  double thickness_m = 0.05;  // depth of the box
  double margin = 1.25;       // wall size over the frustum's cross-section at distance_m
  double restitution = 0.3;   // bounce of fragments off the wall
};

const ParamSpec<WallParams>& wall_param_spec();

}  // namespace fragsim
