#pragma once
// `near-plane`'s parameters and their scene keys ([near-plane]).

#include "strategies/param_spec.hpp"

namespace fragsim {

struct NearPlaneParams {
  double min_near_m = 0.01;      // the near plane never comes closer than this
  double margin_m = 0.02;        // kept between the near plane and the nearest fragment
  int depth_bits = 24;           // depth buffer precision, for the depth-step report
  double ref_distance_m = 10.0;  // distance at which the depth step is reported
};

const ParamSpec<NearPlaneParams>& near_plane_param_spec();

}  // namespace fragsim
