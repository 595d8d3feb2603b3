#pragma once
// A scene's strategies: the registry (strategies/registry.hpp) fed the scene's settings. The
// strategies know nothing of scenes; this is where the simulation's side meets them.

#include <memory>
#include <string_view>

#include "sim/scene.hpp"
#include "strategies/registry.hpp"

namespace fragsim {

inline StrategySettings strategy_settings(const Scene& scene) {
  StrategySettings s;
  s.wall = scene.wall;
  s.deflect_all = scene.deflect_all;
  s.near_plane = scene.near_plane;
  s.edge = scene.edge;
  s.edge_min = scene.edge_min;
  s.camera_fovy_deg = scene.camera.fovy_deg;
  s.camera_aspect = scene.camera.aspect;
  s.camera_near_m = scene.camera.near_m;
  return s;
}

// The named strategy with its parameters taken from the scene's section of the same name.
inline std::unique_ptr<Strategy> make_strategy(std::string_view name, const Scene& scene) {
  return make_strategy(name, strategy_settings(scene));
}

}  // namespace fragsim
