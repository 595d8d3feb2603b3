#include "experiments/time_vs_error.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <ostream>
#include <stdexcept>

#include "experiments/accuracy_probe.hpp"
#include "experiments/median.hpp"
#include "io/number_format.hpp"
#include "metrics/near_plane_metric.hpp"
#include "sim/scene_strategies.hpp"
#include "sim/simulation.hpp"
#include "strategies/registry.hpp"

namespace fragsim {
namespace {

SceneOverride key(const std::string& k, const std::string& v) {
  return {k, v};
}

std::string dt_value(int per_second) {
  return format_double(1.0 / per_second);
}

struct Measured {
  BenchRow row;
  std::vector<std::vector<Eigen::Vector3d>> samples;
  std::vector<char> ever_candidate;
  std::vector<double> first_contact_s;
};

struct Timing {
  std::vector<double> compute_s, physics_ms, strategy_ms;
};

// One run of one configuration. Its timings go to `timing`; the first run's results go to `m`, and
// later runs must reproduce them.
void run_once(const Scene& scene, const TimeVsErrorOptions& o, bool first, Measured& m,
              Timing& timing) {
  auto strategy = make_strategy(o.strategy, scene);
  NearPlaneMetric near;
  AccuracyProbe probe(o.sample_dt_s, strategy->path_predictor());
  RunObserver* observers[] = {&near, &probe};
  const RunTotals totals = simulate(scene, *strategy, observers);
  timing.compute_s.push_back((totals.physics_s + totals.strategy_s) / scene.sim.duration_s);
  timing.physics_ms.push_back(1e3 * totals.physics_s / totals.steps);
  timing.strategy_ms.push_back(1e3 * totals.strategy_s / totals.steps);

  RunSummary s;
  near.fill(s);
  int candidates = 0;
  for (char c : probe.ever_candidate()) candidates += c;
  if (first) {
    m.row.dt_s = scene.sim.dt_s;
    m.row.steps = totals.steps;
    m.row.near_fragments = s.intersections.near_fragments;
    m.row.camera_hit_fragments = s.intersections.camera_hit_fragments;
    m.row.candidates = candidates;
    m.row.predicted_contacts = probe.predicted_contacts();
    m.row.prediction_error_mean_m = probe.prediction_error_mean_m();
    m.row.prediction_error_max_m = probe.prediction_error_max_m();
    m.samples = probe.samples();
    m.ever_candidate = probe.ever_candidate();
    m.first_contact_s = probe.first_contact_s();
  } else if (s.intersections.near_fragments != m.row.near_fragments ||
             s.intersections.camera_hit_fragments != m.row.camera_hit_fragments ||
             candidates != m.row.candidates || probe.samples() != m.samples) {
    // Timing repeats must be the same run; a difference is a determinism bug, not noise.
    throw std::runtime_error("bench config '" + m.row.config.name +
                             "': repeated runs differ (a determinism bug)");
  }
}

void compare_with_reference(Measured& m, const Measured& ref, double sample_dt_s) {
  BenchRow& row = m.row;
  const std::size_t samples = std::min(m.samples.size(), ref.samples.size());
  double sum_m = 0.0, flight_sum_m = 0.0;
  long count = 0, flight_count = 0;
  for (std::size_t j = 0; j < samples; ++j) {
    // With the 1e-9 s, a sample at the very step of first contact is not flight.
    const double t_s = static_cast<double>(j + 1) * sample_dt_s + 1e-9;
    for (std::size_t i = 0; i < m.samples[j].size(); ++i) {
      const double e = (m.samples[j][i] - ref.samples[j][i]).norm();
      sum_m += e;
      ++count;
      row.position_error_max_m = std::max(row.position_error_max_m, e);
      if (t_s < m.first_contact_s[i] && t_s < ref.first_contact_s[i]) {
        flight_sum_m += e;
        ++flight_count;
        row.flight_error_max_m = std::max(row.flight_error_max_m, e);
      }
    }
  }
  row.position_error_mean_m = count > 0 ? sum_m / static_cast<double>(count) : 0.0;
  row.flight_error_mean_m =
      flight_count > 0 ? flight_sum_m / static_cast<double>(flight_count) : 0.0;
  row.near_difference = std::abs(row.near_fragments - ref.row.near_fragments);
  row.camera_hit_difference = std::abs(row.camera_hit_fragments - ref.row.camera_hit_fragments);
  row.candidate_difference = 0;
  for (std::size_t i = 0; i < m.ever_candidate.size(); ++i) {
    row.candidate_difference += m.ever_candidate[i] != ref.ever_candidate[i] ? 1 : 0;
  }
}

std::string overrides_text(const std::vector<SceneOverride>& overrides) {
  std::string s;
  for (const SceneOverride& o : overrides) s += (s.empty() ? "" : "; ") + o.key + "=" + o.value;
  return s;
}

// Quoted per RFC 4180 when it holds a comma, a quote or a line break.
std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string q = "\"";
  for (char c : text) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

}  // namespace

std::vector<BenchConfig> standard_bench_configs(const std::string& strategy) {
  std::vector<BenchConfig> c;
  c.push_back({"default", "default", {}});
  for (int hz : {30, 60, 120, 240, 480}) {
    c.push_back({"dt 1/" + std::to_string(hz), "dt", {key("simulation.dt_s", dt_value(hz))}});
  }
  c.push_back({"exact", "solver", {key("simulation.solver", "exact")}});
  for (int it : {5, 10, 20, 40}) {
    c.push_back({"quick " + std::to_string(it),
                 "solver",
                 {key("simulation.solver", "quick"),
                  key("simulation.solver_iterations", std::to_string(it))}});
  }
  // The skips of resting fragments (world.cpp), each alone and both.
  c.push_back({"auto-disable", "skip", {key("simulation.auto_disable", "on")}});
  c.push_back({"cull resting", "skip", {key("simulation.cull_resting", "on")}});
  c.push_back({"auto-disable + cull",
               "skip",
               {key("simulation.auto_disable", "on"), key("simulation.cull_resting", "on")}});
  // Then the strategy's own accuracy settings, as it declares them.
  if (const StrategyEntry* entry = find_strategy(strategy)) {
    for (const TuningVariant& v : entry->tuning) {
      BenchConfig config{v.label, v.group, {}};
      for (const auto& [k, value] : v.keys) config.overrides.push_back(key(k, value));
      c.push_back(std::move(config));
    }
  }
  return c;
}

BenchConfig reference_bench_config() {
  return {"reference",
          "reference",
          {key("simulation.dt_s", dt_value(480)), key("simulation.solver", "exact")}};
}

std::vector<BenchRow> run_time_vs_error(const Scene& base, const std::vector<BenchConfig>& configs,
                                        const BenchConfig& reference,
                                        const TimeVsErrorOptions& options,
                                        const std::function<void(const BenchRow&)>& progress,
                                        std::vector<BenchDuplicate>* duplicates) {
  if (options.repeats < 1) throw std::invalid_argument("repeats must be at least 1");
  const std::string base_text = scene_to_ini(base);
  auto resolve = [&](const BenchConfig& c) {
    Scene s;
    try {
      s = parse_scene(base_text, "bench config '" + c.name + "'", c.overrides);
    } catch (const SceneError& e) {
      throw SceneError("bench config '" + c.name + "': " + e.what());
    }
    if (s.fragment_count() != base.fragment_count()) {
      throw SceneError("bench config '" + c.name + "': changes the number of fragments");
    }
    const double ratio = options.sample_dt_s / s.sim.dt_s;
    if (std::abs(ratio - std::round(ratio)) > 1e-6 * ratio || ratio < 0.5) {
      throw SceneError(
          "bench config '" + c.name + "': simulation.dt_s = " + format_double(s.sim.dt_s) +
          " does not divide the sample interval " + format_double(options.sample_dt_s) + " s");
    }
    validate_strategy_settings(options.strategy, s);  // bad parameters fail before anything runs
    return s;
  };
  // Two configurations are the same simulation when their scenes agree once `auto` is replaced by
  // the solver it picks (in world.cpp, exact unless fragments collide or a wall is needed).
  const bool wall = make_strategy(options.strategy, base)->needs().camera_wall.has_value();
  auto identity = [&](Scene s) {
    if (s.sim.solver == Solver::kAuto) {
      s.sim.solver = s.sim.uses_exact_solver() && !wall ? Solver::kExact : Solver::kQuick;
    }
    if (s.sim.solver == Solver::kExact) s.sim.solver_iterations = 20;  // QuickStep's only
    return scene_to_ini(s);
  };
  // Everything is resolved before the first run, so a bad configuration costs no waiting.
  const Scene ref_scene = resolve(reference);
  std::vector<std::pair<BenchConfig, Scene>> plan;
  std::map<std::string, std::string> seen{{identity(ref_scene), reference.name}};
  for (const BenchConfig& c : configs) {
    Scene s = resolve(c);
    const auto [it, added] = seen.emplace(identity(s), c.name);
    if (!added) {
      if (duplicates) duplicates->push_back({c.name, it->second});
      continue;
    }
    plan.emplace_back(c, std::move(s));
  }

  // Round 0 measures everything; later rounds repeat every configuration in the same order, so
  // a busy spell on a shared machine spreads over all of them instead of spoiling one.
  plan.insert(plan.begin(), {reference, ref_scene});
  std::vector<Measured> measured(plan.size());
  std::vector<Timing> timing(plan.size());
  for (int round = 0; round < options.repeats; ++round) {
    for (std::size_t k = 0; k < plan.size(); ++k) {
      if (round == 0) measured[k].row.config = plan[k].first;
      run_once(plan[k].second, options, round == 0, measured[k], timing[k]);
      if (round == 0 && progress) progress(measured[k].row);
    }
  }
  std::vector<BenchRow> rows;
  for (std::size_t k = 0; k < plan.size(); ++k) {
    Measured& m = measured[k];
    if (k > 0) compare_with_reference(m, measured[0], options.sample_dt_s);
    m.row.compute_s_per_sim_s = median(timing[k].compute_s);
    m.row.physics_ms_per_step = median(timing[k].physics_ms);
    m.row.strategy_ms_per_step = median(timing[k].strategy_ms);
    rows.push_back(m.row);
  }
  mark_pareto_front(rows);
  return rows;
}

void mark_pareto_front(std::vector<BenchRow>& rows) {
  for (BenchRow& a : rows) {
    a.pareto = std::none_of(rows.begin(), rows.end(), [&](const BenchRow& b) {
      const bool no_worse = b.compute_s_per_sim_s <= a.compute_s_per_sim_s &&
                            b.flight_error_mean_m <= a.flight_error_mean_m;
      const bool better = b.compute_s_per_sim_s < a.compute_s_per_sim_s ||
                          b.flight_error_mean_m < a.flight_error_mean_m;
      return no_worse && better;
    });
  }
}

void write_time_vs_error_csv(std::ostream& out, const std::vector<BenchRow>& rows) {
  out << "config,group,overrides,dt_s,steps,compute_s_per_sim_s,physics_ms_per_step,"
         "strategy_ms_per_step,flight_error_mean_m,flight_error_max_m,position_error_mean_m,"
         "position_error_max_m,near_fragments,"
         "near_difference,camera_hit_fragments,camera_hit_difference,candidates,"
         "candidate_difference,predicted_contacts,prediction_error_mean_m,"
         "prediction_error_max_m,pareto\n";
  for (const BenchRow& r : rows) {
    std::string line = csv_field(r.config.name) + "," + csv_field(r.config.group) + "," +
                       csv_field(overrides_text(r.config.overrides)) + ",";
    append_double(line, r.dt_s);
    line += "," + std::to_string(r.steps) + ",";
    for (double v : {r.compute_s_per_sim_s, r.physics_ms_per_step, r.strategy_ms_per_step,
                     r.flight_error_mean_m, r.flight_error_max_m, r.position_error_mean_m,
                     r.position_error_max_m}) {
      append_double(line, v);
      line += ",";
    }
    for (int v :
         {r.near_fragments, r.near_difference, r.camera_hit_fragments, r.camera_hit_difference,
          r.candidates, r.candidate_difference, r.predicted_contacts}) {
      line += std::to_string(v) + ",";
    }
    append_double(line, r.prediction_error_mean_m);
    line += ",";
    append_double(line, r.prediction_error_max_m);
    line += r.pareto ? ",1\n" : ",0\n";
    out << line;
  }
}

}  // namespace fragsim
