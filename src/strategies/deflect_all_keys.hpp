#pragma once
// `deflect-all`'s scene keys ([deflect-all]) are the library's DeflectAllParams as text, each
// number's range the library's (kDeflectAllRanges).

#include "control/strategies/deflect_all_params.hpp"
#include "strategies/param_spec.hpp"

namespace fragsim {

const ParamSpec<DeflectAllParams>& deflect_all_param_spec();

}  // namespace fragsim
