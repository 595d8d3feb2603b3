#pragma once
// `edge`'s scene keys ([edge]) are the library's EdgeParams as text, each number's range the
// library's (kEdgeRanges).

#include "control/strategies/edge_params.hpp"
#include "strategies/param_spec.hpp"

namespace fragsim {

const ParamSpec<EdgeParams>& edge_param_spec();

}  // namespace fragsim
