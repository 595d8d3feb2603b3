#include "metrics/evaluation.hpp"

#include <array>

#include "metrics/cost_metric.hpp"
#include "metrics/near_plane_metric.hpp"
#include "metrics/strategy_activity_metric.hpp"
#include "sim/simulation.hpp"
#include "strategies/registry.hpp"

namespace fragsim {

Evaluation evaluate(const Scene& scene, const std::string& strategy_name) {
  auto strategy = make_strategy(strategy_name, scene);
  NearPlaneMetric near;
  StrategyActivityMetric activity(scene.near_plane.depth_bits, scene.near_plane.ref_distance_m);
  CostMetric cost;
  const std::array<RunObserver*, 3> observers{&near, &activity, &cost};
  const RunTotals totals = simulate(scene, *strategy, observers);

  Evaluation e;
  RunSummary& s = e.summary;
  s.scene = scene.name;
  s.strategy = strategy->name();
  s.seed = scene.sim.seed;
  s.dt_s = scene.sim.dt_s;
  s.fragments = scene.fragment_count();
  s.steps = totals.steps;
  s.wall_s = totals.wall_s;
  near.fill(s);
  activity.fill(s);
  cost.fill(s);
  e.near_per_step = near.per_step();
  e.candidates_per_step = activity.candidates_per_step();
  e.near_m_per_step = activity.near_per_step_m();
  return e;
}

}  // namespace fragsim
