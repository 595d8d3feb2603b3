#pragma once
// Strategies by name: the one place that knows every implementation. It knows nothing of the
// scene or the simulation (the strategies are the bottom layer): the simulation hands it the
// settings (sim/scene_strategies.hpp makes them from a scene).

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "strategies/strategy.hpp"
#include "strategies/strategy_params.hpp"

namespace fragsim {

// Every strategy name, in the order comparisons list them.
const std::vector<std::string>& strategy_names();

// What the strategies are made from: each one's parameters, and the camera's frustum the wall is
// sized to and the near plane is pulled in from.
struct StrategySettings {
  WallParams wall;
  DeflectAllParams deflect_all;
  NearPlaneParams near_plane;
  EdgeParams edge;
  EdgeMinParams edge_min;
  double camera_fovy_deg = 60.0;
  double camera_aspect = 16.0 / 9.0;
  double camera_near_m = 0.1;
};

// A new strategy with its parameters. Throws std::invalid_argument naming the strategy (unknown
// name) or the parameter and its value.
std::unique_ptr<Strategy> make_strategy(std::string_view name, const StrategySettings& settings);

}  // namespace fragsim
