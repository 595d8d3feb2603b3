#pragma once
// `edge-min`'s scene keys ([edge-min]) are the library's EdgeMinParams as text, each number's range
// the library's (kEdgeMinRanges).

#include "control/strategies/edge_min_params.hpp"
#include "strategies/param_spec.hpp"

namespace fragsim {

const ParamSpec<EdgeMinParams>& edge_min_param_spec();

}  // namespace fragsim
