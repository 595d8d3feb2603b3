#pragma once
// A whole run at once, a Run (run.hpp) stepped from the explosion to the scene's last step.

#include <span>

#include "sim/run.hpp"
#include "sim/run_observer.hpp"
#include "sim/scene.hpp"
#include "strategies/scene_strategy.hpp"

namespace fragsim {

RunTotals simulate(const Scene& scene, SceneStrategy& strategy,
                   std::span<RunObserver* const> observers = {});
// The same with the camera's motion given by the caller instead of made from camera.mode (see
// Run's constructor for what it is asked).
RunTotals simulate(const Scene& scene, SceneStrategy& strategy, const CameraMotion& camera,
                   std::span<RunObserver* const> observers = {});

}  // namespace fragsim
