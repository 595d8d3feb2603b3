#pragma once
// The built-in strategies' parameters, each declared with its scene keys (for the library's
// strategies, structs in src/control, keys in the tool's *_keys.hpp). For code that uses several of
// them (the scene, the prediction shared by edge and edge-min).

#include "strategies/deflect_all_keys.hpp"
#include "strategies/edge_keys.hpp"
#include "strategies/edge_min_keys.hpp"
#include "strategies/near_plane_params.hpp"
#include "strategies/wall_params.hpp"
