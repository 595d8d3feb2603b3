#pragma once
// `deflect-all`'s parameters and their scene keys ([deflect-all]).

#include "strategies/param_spec.hpp"

namespace fragsim {

struct DeflectAllParams {
  double accel_mps2 = 60.0;  // push away from the view axis, per unit mass
  double range_m = 6.0;      // only fragments closer than this to the eye are pushed
};

const ParamSpec<DeflectAllParams>& deflect_all_param_spec();

}  // namespace fragsim
