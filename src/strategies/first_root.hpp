#pragma once
// The root solver moved to geometry/first_root.hpp. This forwarding header keeps the includes of
// code that has not switched yet compiling (edge_min_strategy.cpp); remove it once none is left.

#include "geometry/first_root.hpp"
