#pragma once
// One run's headline numbers, a row of the comparison table and of summary.csv, in parts by
// concern. Each metric observer fills its own part.

#include <cstdint>
#include <functional>
#include <string>
#include <variant>
#include <vector>

namespace fragsim {

// Near-plane intersections (swept) and camera-body hits (near_plane_metric), the passes that
// nearly were (exit_metric), and the fade's way of hiding them (vanished_metric).
struct IntersectionCounts {
  int near_fragment_steps = 0;
  int near_fragments = 0;
  int camera_hit_fragments = 0;
  int near_misses = 0;  // passed within the near-miss distance without touching the near rectangle
  // Fragments that faded below half opacity in view, or met the near plane invisible (fade).
  int vanished_fragments = 0;
};

// Trajectory deviation against the `none` run of the same scene and seed (deviation_metric).
struct DeviationStats {
  double mean_m = 0.0;          // mean over fragments of each one's largest deviation
  double max_m = 0.0;           // largest deviation of any fragment
  double deviated_share = 0.0;  // share of fragments moved more than 1 cm
};

// Screen occlusion (occlusion_metric), the covered share of the viewport and of the central region.
struct OcclusionStats {
  double mean = 0.0;
  double max = 0.0;
  double central_mean = 0.0;
  double central_max = 0.0;
  double single_fragment_max = 0.0;  // largest share covered by one fragment
};

// How fragments that were on screen left it (exit_metric).
struct ExitCounts {
  int top = 0;
  int bottom = 0;
  int left = 0;
  int right = 0;
  int near = 0;    // through the near plane
  int stayed = 0;  // still on screen at the end
};

// What the strategy did over the run (strategy_activity_metric).
struct ActivityTotals {
  int candidates_initial = 0;  // after the prediction at t = 0
  int candidates_max = 0;
  int candidate_steps = 0;      // sum over steps
  int capped_forces = 0;        // force-steps reduced by the acceleration cap
  int unsaved_by_cap = 0;       // capped fragments that still met the near rectangle or camera
  int guarded = 0;              // singular spots guarded (t_C - t -> 0, |P_pc| -> 0)
  int deferred = 0;             // fragment-steps a per-step budget left unsolved (edge-min)
  int forced_fragments = 0;     // fragments that got any force
  double impulse_Ns = 0.0;      // sum of |F| dt over the run
  double max_accel_mps2 = 0.0;  // largest imposed acceleration
  int wall_contacts = 0;        // contact points with the wall (wall)
  double min_near_m = 0.0;      // smallest near distance used (near-plane pulls it in)
  double depth_step_m = 0.0;    // depth resolution at the reference distance with min_near_m
};

// Health of the run's physics.
struct PhysicsHealth {
  int ode_messages = 0;         // warnings ODE printed
  int nonfinite_fragments = 0;  // fragments whose state became non-finite (frozen, counted)
};

// Wall time (cost_metric), the only part that differs between two runs of the same scene.
struct RunCost {
  double physics_ms_median = 0.0;
  double physics_ms_p95 = 0.0;
  double strategy_ms_median = 0.0;
  double strategy_ms_p95 = 0.0;
  double wall_s = 0.0;
};

struct RunSummary {
  std::string scene;
  std::string strategy;
  std::uint64_t seed = 0;
  double dt_s = 0.0;
  int fragments = 0;
  int steps = 0;

  IntersectionCounts intersections;
  DeviationStats deviation;
  OcclusionStats occlusion;
  ExitCounts exits;
  // The exits of the pushed fragments only (those that got any force), where a push sent them. A
  // pushed fragment never on screen is in none of these.
  ExitCounts pushed_exits;
  ActivityTotals activity;
  PhysicsHealth health;
  RunCost cost;
};

// summary.csv's columns in order, each one's header and where in RunSummary its value is, the one
// list behind summary.csv, its reader and the codec that carries a summary between processes.
struct SummaryField {
  template <class T>
  using Get = std::function<T*(RunSummary&)>;
  const char* name;
  std::variant<Get<int>, Get<double>, Get<std::string>, Get<std::uint64_t>> field;
};
const std::vector<SummaryField>& summary_field_table();

// Every summary.csv field of a run as text (the deterministic part of RunSummary, all but the
// timings), and back, so a run's summary crosses a process boundary exactly.
std::vector<std::string> summary_fields(const RunSummary& summary);
void set_summary_fields(RunSummary& summary, const std::vector<std::string>& fields);

}  // namespace fragsim
