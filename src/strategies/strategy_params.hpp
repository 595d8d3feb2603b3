#pragma once
// The built-in strategies' parameters, each declared in its own file with its scene keys. For
// code that uses several of them (the scene, the prediction shared by edge and edge-min).

#include "strategies/deflect_all_params.hpp"
#include "strategies/edge_min_params.hpp"
#include "strategies/edge_params.hpp"
#include "strategies/near_plane_params.hpp"
#include "strategies/wall_params.hpp"
