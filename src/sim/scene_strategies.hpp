#pragma once
// A scene's strategies, the registry (strategies/registry.hpp) fed the scene's settings. The
// strategies know nothing of scenes; this is where the simulation's side meets them.

#include <memory>
#include <string_view>

#include "sim/scene.hpp"
#include "strategies/registry.hpp"

namespace fragsim {

// Whether the named strategy can be made from the scene's section of the same name, without
// making it. Throws InputError, as make_strategy would.
inline void validate_strategy_settings(std::string_view name, const Scene& scene) {
  validate_strategy_settings(name, scene.strategies, scene.camera.frustum_def());
}

// The named strategy with its parameters taken from the scene's section of the same name.
// Throws InputError.
inline std::unique_ptr<SceneStrategy> make_strategy(std::string_view name, const Scene& scene) {
  return make_strategy(name, scene.strategies, scene.camera.frustum_def());
}

}  // namespace fragsim
