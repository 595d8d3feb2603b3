#include "experiments/suite.hpp"

#include <algorithm>
#include <cstring>
#include <set>
#include <sstream>
#include <tuple>

#include "experiments/evaluation.hpp"
#include "experiments/evaluation_codec.hpp"
#include "experiments/median.hpp"
#include "experiments/process_runner.hpp"
#include "experiments/shard.hpp"
#include "io/input_file.hpp"
#include "io/number_format.hpp"
#include "metrics/trajectory_record.hpp"
#include "sim/scene_strategies.hpp"

namespace fragsim {
namespace {

// edge-min's camera models (the scene key edge-min.camera_model), each a row of its own.
const std::vector<std::string>& edge_min_camera_models() {
  static const std::vector<std::string> models{"constant", "bounded_accel", "reachable"};
  return models;
}

SuiteOutcome outcome_of(const RunSummary& s, std::size_t run, const std::string& label) {
  SuiteOutcome o;
  o.run = run;
  o.variant = label;
  o.near_fragments = s.intersections.near_fragments;
  o.camera_hits = s.intersections.camera_hit_fragments;
  o.vanished = s.intersections.vanished_fragments;
  o.deviation_mean_m = s.deviation.mean_m;
  o.near_misses = s.intersections.near_misses;
  o.strategy_ms_median = s.cost.strategy_ms_median;
  return o;
}

// The run's scene with the variant's keys, as the worker builds it.
Scene variant_scene(const std::string& text, const SuiteRun& run, const SuiteVariant& v) {
  std::vector<SceneOverride> o = suite_overrides(run);
  o.insert(o.end(), v.overrides.begin(), v.overrides.end());
  return parse_scene(text, run.scene + ".ini", o);
}

}  // namespace

const std::vector<SuiteSceneSpec>& suite_scene_specs() {
  // Distances and speeds are chosen so that `none` keeps the camera clean in well under half of the
  // runs (16% of the path runs at 9 seeds, measured) while each scene keeps its character, with the
  // scene's own distance and a closer one, its own aim speed and a faster one.
  static const std::vector<SuiteSceneSpec> specs{
      {"front", {"6", "10"}, {"10", "15"}},   {"thesis125", {"4", "7"}, {"3", "6"}},
      {"thesis1000", {"4", "7"}, {"3", "6"}}, {"close", {"1.5", "2.2"}, {"6", "9"}},
      {"distance", {"5", "10"}, {"8", "12"}},
  };
  return specs;
}

const std::vector<std::string>& suite_aims() {
  static const std::vector<std::string> aims{"future", "present"};
  return aims;
}

const std::vector<SuiteMode>& suite_modes() {
  static const std::vector<SuiteMode> modes{
      {"path", {{"camera.mode", "path"}}},
      {"player", {{"camera.mode", "player"}}},
      {"player-instant", {{"camera.mode", "player"}, {"camera.player_accel_mps2", "inf"}}},
      // A mouse flick's turn rate (eight times the scene default), because edge-min must not rely
      // on a slow view.
      {"player-flick", {{"camera.mode", "player"}, {"camera.turn_rate_degps", "720"}}},
  };
  return modes;
}

bool is_player_mode(const std::string& mode) {
  for (const SuiteMode& m : suite_modes()) {
    if (m.name != mode) continue;
    for (const SceneOverride& o : m.overrides) {
      if (o.key == "camera.mode" && o.value == "player") return true;
    }
  }
  return false;
}

std::vector<SuiteVariant> suite_variants() {
  std::vector<SuiteVariant> out{{"none", "none", {}}};
  for (const std::string& name : strategy_names()) {
    if (name == "none") continue;
    if (name == "edge-min") {
      for (const std::string& model : edge_min_camera_models()) {
        out.push_back({name + "/" + model, name, {{"edge-min.camera_model", model}}});
      }
    } else {
      out.push_back({name, name, {}});
    }
  }
  return out;
}

std::vector<SuiteRun> suite_runs(const SuiteSelection& sel) {
  if (sel.seeds < 1 || sel.seeds > kSuiteMaxSeeds) {
    throw SuiteError("must be a whole number in [1, " + std::to_string(kSuiteMaxSeeds) + "]");
  }
  const auto& specs = suite_scene_specs();
  for (const std::string& s : sel.scenes) {
    if (std::none_of(specs.begin(), specs.end(),
                     [&s](const SuiteSceneSpec& spec) { return spec.scene == s; })) {
      std::string names;
      for (const SuiteSceneSpec& spec : specs) names += (names.empty() ? "" : ", ") + spec.scene;
      throw SuiteError("'" + s + "' is not a battery scene (" + names + ")");
    }
  }
  const auto& modes = suite_modes();
  for (const std::string& m : sel.modes) {
    if (std::none_of(modes.begin(), modes.end(),
                     [&m](const SuiteMode& mode) { return mode.name == m; })) {
      std::string names;
      for (const SuiteMode& mode : modes) names += (names.empty() ? "" : ", ") + mode.name;
      throw SuiteError("'" + m + "' is not a battery mode (" + names + ")");
    }
  }
  auto chosen = [](const std::vector<std::string>& list, const std::string& name) {
    return list.empty() || std::find(list.begin(), list.end(), name) != list.end();
  };
  std::vector<SuiteRun> runs;
  // Table order, not selection order, so a slice's rows are in the full battery's order.
  for (const SuiteSceneSpec& spec : specs) {
    if (!chosen(sel.scenes, spec.scene)) continue;
    for (const std::string& d : spec.distances_m) {
      for (const std::string& aim : suite_aims()) {
        for (const std::string& v : spec.toward_camera_mps) {
          for (const SuiteMode& mode : modes) {
            if (!chosen(sel.modes, mode.name)) continue;
            for (int seed = 1; seed <= sel.seeds; ++seed) {
              runs.push_back({spec.scene, d, aim, v, mode.name, static_cast<std::uint64_t>(seed)});
            }
          }
        }
      }
    }
  }
  if (sel.limit > 0 && runs.size() > sel.limit) runs.resize(sel.limit);
  return runs;
}

std::vector<SceneOverride> suite_overrides(const SuiteRun& run) {
  std::vector<SceneOverride> o{{"object.distance_m", run.distance_m},
                               {"explosion.aim", run.aim},
                               {"explosion.toward_camera_mps", run.toward_camera_mps}};
  for (const SuiteMode& m : suite_modes()) {
    if (m.name == run.mode) o.insert(o.end(), m.overrides.begin(), m.overrides.end());
  }
  o.push_back({"simulation.seed", std::to_string(run.seed)});
  return o;
}

std::map<std::string, std::string> load_suite_scenes(const std::string& dir,
                                                     const std::vector<SuiteRun>& runs) {
  std::map<std::string, std::string> out;
  for (const SuiteRun& r : runs) {
    if (out.count(r.scene)) continue;
    const std::string path = dir + "/" + r.scene + ".ini";
    try {
      out.emplace(r.scene, read_text_file(path, "battery scene file"));
    } catch (const InputError& e) {
      throw SuiteError(e.what());
    }
  }
  return out;
}

void validate_suite(const std::map<std::string, std::string>& scenes,
                    const std::vector<SuiteRun>& runs, const std::vector<SuiteVariant>& variants) {
  // The seed cannot make a scene invalid, so one seed per entry and mode covers every run.
  std::set<std::tuple<std::string, std::string, std::string, std::string, std::string>> seen;
  for (const SuiteRun& r : runs) {
    if (!seen.insert({r.scene, r.distance_m, r.aim, r.toward_camera_mps, r.mode}).second) continue;
    for (const SuiteVariant& v : variants) {
      const Scene scene = variant_scene(scenes.at(r.scene), r, v);
      validate_strategy_settings(v.strategy, scene);
    }
  }
}

std::vector<SuiteOutcome> run_suite_once(const std::string& scene_text, const SuiteRun& run,
                                         std::size_t run_index,
                                         const std::vector<SuiteVariant>& variants) {
  const Scene base = variant_scene(scene_text, run, {"none", "none", {}});
  TrajectoryRecord reference;
  EvaluationOptions ref_opts;
  ref_opts.record = &reference;
  ref_opts.occlusion = false;  // the suite reads no occlusion metric; the raster is costly
  const Evaluation none = evaluate(base, "none", ref_opts);
  EvaluationOptions opts;
  opts.reference = &reference;
  opts.occlusion = false;
  std::vector<SuiteOutcome> out;
  for (const SuiteVariant& v : variants) {
    if (v.strategy == "none" && v.overrides.empty()) {
      // The reference itself, whose deviation from itself is zero.
      out.push_back(outcome_of(none.summary, run_index, v.label));
      continue;
    }
    const Scene scene = v.overrides.empty() ? base : variant_scene(scene_text, run, v);
    out.push_back(outcome_of(evaluate(scene, v.strategy, opts).summary, run_index, v.label));
  }
  return out;
}

std::vector<SuiteOutcome> run_suite(const std::map<std::string, std::string>& scenes,
                                    const std::vector<SuiteRun>& runs,
                                    const std::vector<SuiteVariant>& variants, int jobs,
                                    const std::function<void(std::size_t done)>& on_done) {
  ProcessRunOptions options;
  options.jobs = jobs;
  if (on_done) options.on_done = [&on_done](std::size_t, std::size_t done) { on_done(done); };
  options.describe = [&runs](std::size_t i) {
    const SuiteRun& r = runs[i];
    return "run " + std::to_string(i + 1) + " (" + r.scene + ", object.distance_m " + r.distance_m +
           ", aim " + r.aim + ", explosion.toward_camera_mps " + r.toward_camera_mps + ", mode " +
           r.mode + ", seed " + std::to_string(r.seed) + ")";
  };
  const std::vector<std::string> encoded = run_in_processes(
      runs.size(),
      [&](std::size_t i) {
        // Through the evaluation codec, doubles bit for bit, so a worker's numbers are the
        // parent's; the per-step series are dropped (the suite reads the summaries only).
        std::vector<Evaluation> summaries;
        for (const SuiteOutcome& o :
             run_suite_once(scenes.at(runs[i].scene), runs[i], i, variants)) {
          Evaluation& e = summaries.emplace_back();
          e.summary.strategy = o.variant;
          e.summary.intersections.near_fragments = o.near_fragments;
          e.summary.intersections.camera_hit_fragments = o.camera_hits;
          e.summary.intersections.vanished_fragments = o.vanished;
          e.summary.deviation.mean_m = o.deviation_mean_m;
          e.summary.intersections.near_misses = o.near_misses;
          e.summary.cost.strategy_ms_median = o.strategy_ms_median;
        }
        return encode_evaluations(summaries);
      },
      options);
  std::vector<SuiteOutcome> out;
  out.reserve(runs.size() * variants.size());
  for (std::size_t i = 0; i < encoded.size(); ++i) {
    const std::vector<Evaluation> decoded = decode_evaluations(encoded[i]);
    if (decoded.size() != variants.size()) {
      throw std::runtime_error("suite result of run " + std::to_string(i + 1) +
                               ": variants missing");
    }
    for (std::size_t k = 0; k < variants.size(); ++k) {
      if (decoded[k].summary.strategy != variants[k].label) {
        throw std::runtime_error("suite result of run " + std::to_string(i + 1) +
                                 ": variants out of order");
      }
      out.push_back(outcome_of(decoded[k].summary, i, variants[k].label));
    }
  }
  return out;
}

std::vector<SuiteRow> aggregate_suite(const std::vector<SuiteOutcome>& outcomes,
                                      const std::function<bool(std::size_t run)>& keep) {
  std::map<std::size_t, int> none_misses;  // by run
  for (const SuiteOutcome& o : outcomes) {
    if (o.variant == "none" && (!keep || keep(o.run))) none_misses[o.run] = o.near_misses;
  }
  std::vector<SuiteRow> rows;
  std::map<std::string, std::size_t> at;
  std::vector<std::vector<double>> ms;
  for (const SuiteOutcome& o : outcomes) {
    if (keep && !keep(o.run)) continue;
    auto [it, added] = at.emplace(o.variant, rows.size());
    if (added) {
      rows.push_back({o.variant});
      ms.emplace_back();
    }
    SuiteRow& r = rows[it->second];
    ++r.runs;
    r.clean_runs += o.clean() ? 1 : 0;
    r.deviation_mean_m += o.deviation_mean_m;  // a sum until divided below
    r.near_misses += o.near_misses;
    const auto none = none_misses.find(o.run);
    if (none != none_misses.end()) r.none_near_misses += none->second;
    ms[it->second].push_back(o.strategy_ms_median);
  }
  for (std::size_t i = 0; i < rows.size(); ++i) {
    rows[i].deviation_mean_m /= rows[i].runs;
    rows[i].strategy_ms_median = median(std::move(ms[i]));
  }
  return rows;
}

std::optional<SuiteRecommendation> recommend_suite(const std::vector<SuiteRow>& player,
                                                   const std::vector<SuiteRow>& all) {
  std::optional<SuiteRecommendation> best;
  for (const SuiteRow& row : all) {
    if (row.variant == "none") continue;
    SuiteRecommendation c{row.variant, std::nullopt, row.clean_share(), row.deviation_mean_m};
    for (const SuiteRow& p : player) {
      if (p.variant == row.variant) c.player_clean_share = p.clean_share();
    }
    if (!best) {
      best = c;
      continue;
    }
    // Shares of the same runs, so comparing them compares clean-run counts exactly. A variant
    // missing from the player rows ranks below any that has them.
    const double cp = c.player_clean_share.value_or(-1.0);
    const double bp = best->player_clean_share.value_or(-1.0);
    if (std::make_tuple(-cp, -c.all_clean_share, c.deviation_mean_m) <
        std::make_tuple(-bp, -best->all_clean_share, best->deviation_mean_m)) {
      best = c;
    }
  }
  return best;
}

std::string suite_plan_fingerprint(const std::map<std::string, std::string>& scenes,
                                   const std::vector<SuiteRun>& runs,
                                   const std::vector<SuiteVariant>& variants) {
  PlanText t;
  t.add("fragsim suite plan 1").add(scenes.size());
  for (const auto& [name, text] : scenes) t.add(name).add(text);
  t.add(runs.size());
  for (const SuiteRun& r : runs) {
    t.add(r.scene).add(r.distance_m).add(r.aim).add(r.toward_camera_mps).add(r.mode).add(r.seed);
    const std::vector<SceneOverride> keys = suite_overrides(r);
    t.add(keys.size());
    for (const SceneOverride& o : keys) t.add(o.key).add(o.value);
  }
  t.add(variants.size());
  for (const SuiteVariant& v : variants) {
    t.add(v.label).add(v.strategy).add(v.overrides.size());
    for (const SceneOverride& o : v.overrides) t.add(o.key).add(o.value);
  }
  t.add(suite_csv({}, {}));  // the column header
  return plan_fingerprint(t.text());
}

std::string suite_csv(const std::vector<SuiteRun>& runs,
                      const std::vector<SuiteOutcome>& outcomes) {
  std::string csv =
      "scene,object.distance_m,explosion.aim,explosion.toward_camera_mps,seed,mode,strategy,"
      "near_fragments,camera_hit_fragments,vanished_fragments,deviation_mean_m,near_misses,"
      "strategy_ms_median\n";
  for (const SuiteOutcome& o : outcomes) {
    const SuiteRun& r = runs.at(o.run);
    csv += r.scene + ',' + r.distance_m + ',' + r.aim + ',' + r.toward_camera_mps + ',' +
           std::to_string(r.seed) + ',' + r.mode + ',' + o.variant + ',' +
           std::to_string(o.near_fragments) + ',' + std::to_string(o.camera_hits) + ',' +
           std::to_string(o.vanished) + ',';
    append_double(csv, o.deviation_mean_m);
    csv += ',' + std::to_string(o.near_misses) + ',';
    append_double(csv, o.strategy_ms_median);
    csv += '\n';
  }
  return csv;
}

SuiteTable read_suite_csv(const std::string& csv) {
  std::istringstream in(csv);
  std::string line;
  const std::string header = suite_csv({}, {});
  if (!std::getline(in, line) || line + "\n" != header) {
    throw std::runtime_error("line 1: not the suite CSV's header");
  }
  SuiteTable t;
  int number = 1;
  while (std::getline(in, line)) {
    ++number;
    std::vector<std::string> cells;
    std::istringstream row(line);
    std::string cell;
    while (std::getline(row, cell, ',')) cells.push_back(cell);
    if (cells.size() != 13) {
      throw std::runtime_error("line " + std::to_string(number) + ": expected 13 cells");
    }
    SuiteRun r{cells[0], cells[1], cells[2], cells[3], cells[5], 0};
    SuiteOutcome o;
    try {
      r.seed = std::stoull(cells[4]);
      o.near_fragments = std::stoi(cells[7]);
      o.camera_hits = std::stoi(cells[8]);
      o.vanished = std::stoi(cells[9]);
      o.deviation_mean_m = std::stod(cells[10]);
      o.near_misses = std::stoi(cells[11]);
      o.strategy_ms_median = std::stod(cells[12]);
    } catch (const std::logic_error&) {
      throw std::runtime_error("line " + std::to_string(number) + ": unreadable number");
    }
    o.variant = cells[6];
    // A run's rows are consecutive, so a new run starts where the run's fields change.
    const bool same = !t.runs.empty() && t.runs.back().scene == r.scene &&
                      t.runs.back().distance_m == r.distance_m && t.runs.back().aim == r.aim &&
                      t.runs.back().toward_camera_mps == r.toward_camera_mps &&
                      t.runs.back().mode == r.mode && t.runs.back().seed == r.seed;
    if (!same) t.runs.push_back(r);
    o.run = t.runs.size() - 1;
    t.outcomes.push_back(std::move(o));
  }
  if (!t.runs.empty()) t.variants = t.outcomes.size() / t.runs.size();
  return t;
}

}  // namespace fragsim
