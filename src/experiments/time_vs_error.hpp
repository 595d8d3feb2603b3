#pragma once
// Run time against error (`fragsim bench`), the same scene and strategy under different step sizes,
// solvers, predictors, replanning rules and skips, each timed and compared with a reference run
// (the finest step with the exact solver). Errors: fragment positions at shared sample times,
// near-plane intersections and camera hits, candidate decisions, and the predictor's error at each
// fragment's first contact.

#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "sim/scene.hpp"
#include "sim/scene_file.hpp"

namespace fragsim {

struct BenchConfig {
  std::string name;   // "dt 1/120", "quick 20", ...
  std::string group;  // default | dt | solver | predictor | replan | skip | custom
  std::vector<SceneOverride> overrides;
};

// The configurations the issue asks for, for `strategy` on `base`: the step, the solver and the
// skips, then the strategy's own accuracy settings (its ParamSpec's tuning, e.g. edge's predictor
// and replan). The first one is the scene as given ("default").
std::vector<BenchConfig> standard_bench_configs(const std::string& strategy);

// The finest step the bench tries (1/480 s) with the exact solver.
BenchConfig reference_bench_config();

struct TimeVsErrorOptions {
  std::string strategy = "edge";
  int repeats = 3;                  // timings are the median of this many runs
  double sample_dt_s = 1.0 / 30.0;  // positions are compared every this often
};

struct BenchRow {
  BenchConfig config;
  double dt_s = 0.0;
  int steps = 0;
  // Median over the repeats of physics + strategy time, per simulated second.
  double compute_s_per_sim_s = 0.0;
  double physics_ms_per_step = 0.0;
  double strategy_ms_per_step = 0.0;
  // |position - reference position| over every fragment and sample time at which the fragment is
  // still in flight in both runs, the numerical error of the step and the strategy's pushes.
  double flight_error_mean_m = 0.0;
  double flight_error_max_m = 0.0;
  // The same over all sample times. Once boxes bounce and roll, any difference grows
  // chaotically, so this measures how far apart two runs end up rather than a step's accuracy.
  double position_error_mean_m = 0.0;
  double position_error_max_m = 0.0;
  int near_fragments = 0;
  int camera_hit_fragments = 0;
  int near_difference = 0;        // |near_fragments - the reference's|
  int camera_hit_difference = 0;  // |camera_hit_fragments - the reference's|
  int candidates = 0;             // fragments ever taken for candidates
  int candidate_difference = 0;   // fragments taken for candidates here or there, not both
  int predicted_contacts = 0;     // fragments whose prediction was checked at first contact
  double prediction_error_mean_m = 0.0;
  double prediction_error_max_m = 0.0;
  bool pareto = false;  // no other row is both faster and more accurate (flight error)
};

// A configuration that was not run because it resolves to the same simulation as an earlier one.
struct BenchDuplicate {
  std::string name;
  std::string same_as;
};

// Resolves every configuration on `base` (scene errors name the configuration), drops those that
// resolve to a simulation already listed (into `duplicates` if given), runs the reference and then
// each configuration, in this process and one at a time so timings do not compete, `repeats`
// rounds over all of them. The reference is the first row. `progress` is called after each
// configuration's first run.
std::vector<BenchRow> run_time_vs_error(const Scene& base, const std::vector<BenchConfig>& configs,
                                        const BenchConfig& reference,
                                        const TimeVsErrorOptions& options,
                                        const std::function<void(const BenchRow&)>& progress = {},
                                        std::vector<BenchDuplicate>* duplicates = nullptr);

// Marks the rows no other row dominates in (compute time, mean flight error).
void mark_pareto_front(std::vector<BenchRow>& rows);

void write_time_vs_error_csv(std::ostream& out, const std::vector<BenchRow>& rows);

}  // namespace fragsim
