#include "cli/report_table.hpp"

#include "cli/table.hpp"
#include "sim/world.hpp"

namespace fragsim::cli {
namespace {

std::string percent(double share) {
  return fixed(100.0 * share, 1);
}

}  // namespace

void print_report(const Scene& scene, const std::vector<Evaluation>& runs, std::ostream& out) {
  out << "scene " << scene.name << ": " << scene.fragment_count() << " fragments, "
      << scene.step_count() << " steps of " << fixed(scene.sim.dt_s, 5) << " s, seed "
      << scene.sim.seed << ", ODE " << World::ode_version() << "\n\n";
  Table table({"strategy", "near", "near_st", "cam", "dev_mean_m", "dev_max_m", "dev>1cm_%",
               "occ_mean_%", "occ_max_%", "ctr_max_%", "exits T/B/L/R/N/S", "miss", "cand0",
               "impulse_Ns", "capped", "near_min_m", "phys_ms", "strat_ms"});
  for (const Evaluation& e : runs) {
    const RunSummary& s = e.summary;
    const std::string exits = std::to_string(s.exits_top) + "/" + std::to_string(s.exits_bottom) +
                              "/" + std::to_string(s.exits_left) + "/" +
                              std::to_string(s.exits_right) + "/" + std::to_string(s.exits_near) +
                              "/" + std::to_string(s.exits_stayed);
    table.add_row({s.strategy, std::to_string(s.near_fragments),
                   std::to_string(s.near_fragment_steps), std::to_string(s.camera_hit_fragments),
                   e.has_deviation ? fixed(s.deviation_mean_m, 4) : "-",
                   e.has_deviation ? fixed(s.deviation_max_m, 3) : "-",
                   e.has_deviation ? percent(s.deviated_share) : "-", percent(s.occlusion_mean),
                   percent(s.occlusion_max), percent(s.central_occlusion_max), exits,
                   std::to_string(s.near_misses), std::to_string(s.candidates_initial),
                   fixed(s.impulse_Ns, 2), std::to_string(s.capped_forces), fixed(s.min_near_m, 3),
                   fixed(s.physics_ms_median, 3), fixed(s.strategy_ms_median, 3)});
  }
  table.print(out);
  out << "\nnear: fragments meeting the near rectangle (swept), near_st: fragment-steps, cam: "
         "camera-body hits;\ndev: deviation from the `none` run; occ/ctr: screen and central "
         "share covered; exits: Top/Bottom/Left/Right/Near/Stayed;\nmiss: near misses within "
      << fixed(scene.metrics.near_miss_m, 2)
      << " m; cand0: edge candidates at t = 0; capped: forces cut by a_max; phys/strat: median "
         "per step.\n";
  for (const Evaluation& e : runs) {
    if (e.summary.strategy == "near-plane") {
      out << "near-plane: near distance down to " << fixed(e.summary.min_near_m, 3)
          << " m, depth step at " << fixed(scene.near_plane.ref_distance_m, 1)
          << " m: " << fixed(1e3 * e.summary.depth_step_m, 3) << " mm"
          << (z_fighting(e.summary, scene.near_plane.ref_distance_m) ? " (z-fighting)" : "")
          << "\n";
    }
    if (e.summary.strategy == "wall") {
      out << "wall: " << e.summary.wall_contacts << " contact points with the wall\n";
    }
  }
  out << "cost per step, median / p95:";
  for (const Evaluation& e : runs) {
    const RunSummary& s = e.summary;
    out << (&e == &runs.front() ? " " : "; ") << s.strategy << " " << fixed(s.physics_ms_median, 2)
        << "/" << fixed(s.physics_ms_p95, 2) << " + " << fixed(s.strategy_ms_median, 2) << "/"
        << fixed(s.strategy_ms_p95, 2) << " ms";
  }
  out << " (physics + strategy)\n";
  for (const Evaluation& e : runs) {
    if (e.summary.unsaved_by_cap > 0) {
      out << e.summary.strategy << ": " << e.summary.unsaved_by_cap
          << " fragments the acceleration cap left unsaved (capped and still intersecting)\n";
    }
  }
  if (const auto best = best_for_thesis_goals(runs)) {
    const RunSummary& s = runs[*best].summary;
    const int hits = s.near_fragments + s.camera_hit_fragments;
    out << "best for the thesis's goals (no intersections, then least deviation, then most near "
           "misses): "
        << s.strategy << " (" << (hits == 0 ? "no" : std::to_string(hits)) << " intersections"
        << (runs[*best].has_deviation ? ", mean deviation " + fixed(s.deviation_mean_m, 4) + " m"
                                      : std::string())
        << ", " << s.near_misses << " near misses)\n";
  }
}

}  // namespace fragsim::cli
