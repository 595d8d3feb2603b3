#include "experiments/evaluation.hpp"

#include <tuple>

#include "experiments/control_dump.hpp"
#include "experiments/evaluation_codec.hpp"
#include "experiments/process_runner.hpp"
#include "metrics/camera_track.hpp"
#include "metrics/cost_metric.hpp"
#include "metrics/deviation_metric.hpp"
#include "metrics/exit_metric.hpp"
#include "metrics/near_plane_metric.hpp"
#include "metrics/occlusion_metric.hpp"
#include "metrics/strategy_activity_metric.hpp"
#include "metrics/trajectory_record.hpp"
#include "metrics/vanished_metric.hpp"
#include "sim/scene_strategies.hpp"
#include "sim/simulation.hpp"

namespace fragsim {

Evaluation evaluate(const Scene& scene, const std::string& strategy_name,
                    const EvaluationOptions& options) {
  auto strategy = make_strategy(strategy_name, scene);
  NearPlaneMetric near;
  StrategyActivityMetric activity(scene.strategies.near_plane.depth_bits,
                                  scene.strategies.near_plane.ref_distance_m);
  CostMetric cost;
  ExitMetric exits(scene.metrics);
  CameraTrack camera;
  VanishedMetric vanished;
  std::vector<RunObserver*> observers{&near, &activity, &cost, &exits, &camera, &vanished};
  std::optional<OcclusionMetric> occlusion;
  if (options.occlusion) observers.push_back(&occlusion.emplace(scene.metrics));
  std::optional<DeviationMetric> deviation;
  if (options.reference) {
    observers.push_back(
        &deviation.emplace(*options.reference, scene.metrics.deviation_threshold_m));
  }
  if (options.record) observers.push_back(options.record);
  observers.insert(observers.end(), options.extra.begin(), options.extra.end());

  std::optional<RecordingStrategy> recording;
  if (options.control_dump) recording.emplace(*strategy, *options.control_dump);
  const RunTotals totals =
      simulate(scene, recording ? static_cast<SceneStrategy&>(*recording) : *strategy, observers);

  Evaluation e;
  RunSummary& s = e.summary;
  s.scene = scene.name;
  s.strategy = strategy->name();
  s.seed = scene.sim.seed;
  s.dt_s = scene.sim.dt_s;
  s.fragments = scene.fragment_count();
  s.steps = totals.steps;
  s.cost.wall_s = totals.wall_s;
  s.health.ode_messages = static_cast<int>(totals.ode_messages);
  s.health.nonfinite_fragments = totals.nonfinite_fragments;
  near.fill(s);
  activity.fill(s);
  cost.fill(s);
  exits.fill(s);
  vanished.fill(s, near);
  for (int i = 0; i < s.fragments; ++i) {
    if (activity.was_capped(i) && (near.intersected(i) || near.camera_hit(i)))
      ++s.activity.unsaved_by_cap;
  }
  e.near_per_step = near.per_step();
  e.candidates_per_step = activity.candidates_per_step();
  e.physics_s_per_step = cost.physics_s();
  e.strategy_s_per_step = cost.strategy_s();
  e.camera = camera.poses();
  if (occlusion) {
    occlusion->fill(s);
    e.occlusion_per_step = occlusion->viewport_share_per_step();
    e.central_occlusion_per_step = occlusion->central_share_per_step();
  }
  if (deviation) {
    deviation->fill(s);
    e.has_deviation = true;
  }
  return e;
}

std::vector<Evaluation> compare(const Scene& scene, const std::vector<std::string>& strategies,
                                bool occlusion, RunObserver* extra, int jobs) {
  for (const std::string& name : strategies) validate_strategy_settings(name, scene);  // all first
  TrajectoryRecord reference;
  EvaluationOptions ref_opts;
  ref_opts.record = &reference;
  ref_opts.occlusion = occlusion;
  bool none_named = false;
  for (const std::string& n : strategies) none_named = none_named || n == "none";
  if (none_named && extra) ref_opts.extra.push_back(extra);
  Evaluation none = evaluate(scene, "none", ref_opts);

  // Deviation of the reference from itself is zero by definition.
  none.has_deviation = true;
  EvaluationOptions opts;
  opts.reference = &reference;
  opts.occlusion = occlusion;
  if (extra) opts.extra.push_back(extra);
  std::vector<std::string> others;
  for (const std::string& name : strategies) {
    if (name != "none") others.push_back(name);
  }
  // Workers are forked after the reference run, so each inherits the reference trajectories.
  // An extra observer (a trajectory writer streaming into a file) lives in this process only.
  ProcessRunOptions run;
  run.jobs = extra ? 1 : jobs;
  run.describe = [&others](std::size_t i) { return "strategy " + others[i]; };
  const std::vector<std::string> encoded = run_in_processes(
      others.size(),
      [&](std::size_t i) { return encode_evaluation(evaluate(scene, others[i], opts)); }, run);
  std::vector<Evaluation> runs;
  std::size_t next = 0;
  for (const std::string& name : strategies) {
    runs.push_back(name == "none" ? none : decode_evaluation(encoded[next++]));
  }
  return runs;
}

int thesis_goal_failures(const RunSummary& s) {
  return s.intersections.near_fragments + s.intersections.camera_hit_fragments +
         s.intersections.vanished_fragments;
}

std::optional<std::size_t> best_for_thesis_goals(const std::vector<Evaluation>& runs) {
  std::optional<std::size_t> best;
  auto key = [](const RunSummary& s) {
    return std::make_tuple(thesis_goal_failures(s), s.deviation.mean_m,
                           -s.intersections.near_misses);
  };
  for (std::size_t i = 0; i < runs.size(); ++i) {
    if (runs[i].summary.strategy == "none") continue;
    if (!best || key(runs[i].summary) < key(runs[*best].summary)) best = i;
  }
  return best;
}

bool z_fighting(const RunSummary& s, double ref_distance_m) {
  return s.activity.depth_step_m > 1e-3 * ref_distance_m;
}

}  // namespace fragsim
