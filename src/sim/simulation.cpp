#include "sim/simulation.hpp"

#include <cmath>

namespace fragsim {

int Scene::step_count() const {
  // The last step ends at or just past duration_s; the 1e-9 keeps 3 s / (1/60 s) at 180.
  return static_cast<int>(std::ceil(sim.duration_s / sim.dt_s - 1e-9));
}

RunTotals simulate(const Scene& scene, SceneStrategy& strategy,
                   std::span<RunObserver* const> observers) {
  Run run(scene, strategy, observers);
  while (!run.done()) run.step();
  return run.finish();
}

RunTotals simulate(const Scene& scene, SceneStrategy& strategy, const CameraMotion& camera,
                   std::span<RunObserver* const> observers) {
  Run run(scene, strategy, camera, observers);
  while (!run.done()) run.step();
  return run.finish();
}

}  // namespace fragsim
