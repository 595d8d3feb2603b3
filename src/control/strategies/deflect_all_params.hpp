#pragma once
// `deflect-all`'s parameters and their legal values (the tool's scene keys, [deflect-all], are
// src/strategies/deflect_all_keys.hpp).

#include "control/strategies/param_range.hpp"

namespace fragsim {

struct DeflectAllParams {
  double accel_mps2 = 60.0;  // push away from the view axis, per unit mass
  double range_m = 6.0;      // only fragments closer than this to the eye are pushed
};

// Each numeric field's legal values (param_range.hpp), in the struct's order.
inline constexpr ParamRange kDeflectAllRanges[] = {
    {.name = "accel_mps2", .field = "deflect_all.accel_mps2", .lo = 0, .hi = 1e6},
    {.name = "range_m", .field = "deflect_all.range_m", .lo = 0, .hi = 1e6},
};

}  // namespace fragsim
