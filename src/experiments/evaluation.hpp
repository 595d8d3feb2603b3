#pragma once
// Runs strategies on a scene with the metric observers attached and gathers their summaries and
// per-step series. A comparison runs `none` first, because its trajectories are the reference every
// other strategy's deviation is measured against.

#include <optional>
#include <string>
#include <vector>

#include "control/geometry/camera_pose.hpp"
#include "metrics/run_summary.hpp"
#include "sim/run_observer.hpp"
#include "sim/scene.hpp"

namespace fragsim {

class TrajectoryRecord;
class ControlDump;

struct EvaluationOptions {
  const TrajectoryRecord* reference = nullptr;  // the `none` run for deviation, or null for none
  TrajectoryRecord* record = nullptr;           // filled with this run's trajectories if set
  bool occlusion = true;                        // rasterise the screen every step
  std::vector<RunObserver*> extra;              // more observers (a trajectory writer, ...)
  ControlDump* control_dump = nullptr;          // records the strategy's inputs and forces if set
};

struct Evaluation {
  RunSummary summary;
  bool has_deviation = false;
  // Per-step series, index = step - 1.
  std::vector<int> near_per_step;
  std::vector<int> candidates_per_step;
  std::vector<double> occlusion_per_step;
  std::vector<double> central_occlusion_per_step;
  std::vector<double> physics_s_per_step;
  std::vector<double> strategy_s_per_step;
  std::vector<CameraPose> camera;  // index = step (0 = the explosion)
};

Evaluation evaluate(const Scene& scene, const std::string& strategy,
                    const EvaluationOptions& options = {});

// Every named strategy on the same scene and seed, in the given order; `none` is run first as
// the deviation reference whether named or not (and reported only if named). Unknown names and
// bad parameters throw std::invalid_argument before anything runs. With jobs > 1 and no `extra`
// observer, the strategies after the reference run in that many worker processes
// (process_runner.hpp); the results are the same as with jobs = 1 but for the timings.
std::vector<Evaluation> compare(const Scene& scene, const std::vector<std::string>& strategies,
                                bool occlusion = true, RunObserver* extra = nullptr, int jobs = 1);

// The best of the runs other than `none` by the thesis's goals, in order: no near-plane
// intersections, camera hits or vanished fragments (each one a failure; the sum is compared), then
// least mean deviation, then most near misses. nullopt if there is none.
std::optional<std::size_t> best_for_thesis_goals(const std::vector<Evaluation>& runs);

// The fragments that failed the thesis's goals in a run, cut by the near plane, hitting the
// camera's body, or vanishing on screen (fade). A fragment that vanishes fails them as one that is
// cut does, as the thesis wants debris to leave the picture, not to disappear from it.
int thesis_goal_failures(const RunSummary& s);

// The z-fighting flag, set when the depth step at the reference distance exceeds 1e-3 of it.
bool z_fighting(const RunSummary& summary, double ref_distance_m);

}  // namespace fragsim
