#include "cli/sweep_command.hpp"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <set>

#include "cli/command_line.hpp"
#include "cli/table.hpp"
#include "experiments/evaluation.hpp"
#include "experiments/shard.hpp"
#include "experiments/sweep.hpp"
#include "io/atomic_file.hpp"
#include "io/input_file.hpp"
#include "report/csv_export.hpp"
#include "sim/scene_file.hpp"
#include "sim/scene_strategies.hpp"

namespace fragsim::cli {
namespace {

namespace po = boost::program_options;
namespace fs = std::filesystem;

// The plan and, beside it, what only the command needs.
struct SweepCommandPlan {
  SweepPlan sweep;
  std::string out;
  int jobs = 1;
  std::optional<Shard> shard;  // --shard K/N, only that slice of sweep.jobs
};

// SceneError messages for an override start with "--KEY: "; the caller names --vary instead.
std::string without_option_prefix(const std::string& message, const std::string& key) {
  const std::string prefix = "--" + key + ": ";
  return message.rfind(prefix, 0) == 0 ? message.substr(prefix.size()) : message;
}

// The rows' columns are the varied keys, the seed, then summary.csv's columns but its own seed (the
// same number; a second `seed` column would make readers rename one).
std::vector<std::string> sweep_columns(const SweepPlan& plan, std::size_t& seed_column) {
  std::vector<std::string> cols;
  for (const SweepAxis& a : plan.axes) cols.push_back(a.key);
  cols.emplace_back("seed");
  const std::vector<std::string> summary = summary_csv_columns();
  seed_column = summary.size();
  for (std::size_t i = 0; i < summary.size(); ++i) {
    if (summary[i] == "seed") {
      seed_column = i;
    } else {
      cols.push_back(summary[i]);
    }
  }
  return cols;
}

std::string join(const std::vector<std::string>& cells) {
  std::string s;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    if (i > 0) s += ',';
    s += cells[i];
  }
  return s;
}

// ---- Parsing and validation. Everything that can be wrong is found here, before any fork. ----

SweepCommandPlan plan_sweep(const ParsedCommand& p) {
  SweepCommandPlan command;
  SweepPlan& plan = command.sweep;
  if (!p.options.count("vary")) throw UsageError("--vary: at least one KEY=SPEC is needed");
  std::set<std::string> varied;
  for (const std::string& text : p.options["vary"].as<std::vector<std::string>>()) {
    SweepAxis axis;
    try {
      axis = parse_vary(text);
    } catch (const SweepError& e) {
      throw UsageError("--vary " + text + ": " + e.what());
    }
    if (!scene_options().find_nothrow(axis.key, false)) {
      throw UsageError("--vary " + text + ": unknown scene key '" + axis.key + "'");
    }
    if (axis.key == "simulation.seed") {
      throw UsageError("--vary " + text + ": vary the seed with --seeds N or --seed-list a,b,c");
    }
    if (p.options.count(axis.key)) {
      throw UsageError("--vary " + text + ": --" + axis.key + " is also given; keep one");
    }
    if (!varied.insert(axis.key).second) {
      throw UsageError("--vary " + text + ": " + axis.key + " is varied twice");
    }
    plan.axes.push_back(std::move(axis));
  }

  std::vector<std::uint64_t> seeds;
  const bool n_seeds = p.options.count("seeds") > 0, list = p.options.count("seed-list") > 0;
  if (n_seeds && list) throw UsageError("--seeds and --seed-list: give one");
  if ((n_seeds || list) && p.options.count("simulation.seed")) {
    throw UsageError("--simulation.seed: the sweep's seeds come from --seeds or --seed-list");
  }
  try {
    if (n_seeds) {
      seeds = seeds_up_to(p.options["seeds"].as<long long>());
    } else if (list) {
      seeds = parse_seed_list(p.options["seed-list"].as<std::string>());
    } else {
      seeds = {p.scene.sim.seed};  // the scene's own seed (or --simulation.seed)
    }
  } catch (const SweepError& e) {
    throw UsageError(std::string(n_seeds ? "--seeds: " : "--seed-list: ") + e.what());
  }

  plan.strategies = split_list(p.options["strategies"].as<std::string>());
  if (plan.strategies.empty()) throw UsageError("--strategies: no strategy named");
  std::set<std::string> named;
  for (const std::string& n : plan.strategies) {
    if (!named.insert(n).second) throw UsageError("--strategies: '" + n + "' is named twice");
  }
  for (const std::string& n : plan.strategies) {
    try {
      validate_strategy_settings(n, p.scene);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--strategies: ") + e.what());
    }
  }
  plan.occlusion = p.options.count("no-occlusion") == 0;

  if (!p.options.count("out")) throw UsageError("--out: the output file is needed");
  command.out = p.options["out"].as<std::string>();
  if (command.out.empty()) throw UsageError("--out: empty file name");
  std::error_code ec;
  if (fs::is_directory(command.out, ec)) throw UsageError("--out " + command.out + ": is a folder");
  if (fs::exists(command.out, ec) && !p.options.count("force")) {
    throw UsageError("--out " + command.out + ": exists (use --force to overwrite)");
  }

  command.jobs = jobs_option(p.options);
  if (p.options.count("shard")) {
    try {
      command.shard = parse_shard(p.options["shard"].as<std::string>());
    } catch (const ShardError& e) {
      throw UsageError(std::string("--shard ") + e.what());
    }
  }

  // The scene file's text, read once, as every job's scene is parsed from it with its overrides.
  if (p.options.count("scene")) {
    plan.origin = p.options["scene"].as<std::string>();
    try {
      plan.scene_text = read_text_file(plan.origin, "scene file");
    } catch (const InputError& e) {
      throw UsageError(e.what());
    }
  }
  for (const auto& opt : scene_options().options()) {
    const std::string& key = opt->long_name();
    if (p.options.count(key)) plan.base.push_back({key, p.options[key].as<std::string>()});
  }

  std::vector<std::vector<std::size_t>> combos;
  try {
    combos = sweep_combinations(plan.axes);
    plan.jobs = sweep_jobs(plan.axes, seeds);
  } catch (const SweepError& e) {
    throw UsageError(std::string("--vary: ") + e.what());
  }

  // Each value alone first, so a bad value is reported against its own --vary option.
  for (std::size_t k = 0; k < plan.axes.size(); ++k) {
    const SweepAxis& a = plan.axes[k];
    for (const std::string& v : a.values) {
      std::vector<SceneOverride> o = plan.base;
      o.push_back({a.key, v});
      try {
        parse_scene(plan.scene_text, plan.origin, o);
      } catch (const SceneError& e) {
        throw UsageError("--vary " + a.key + "=" + v + ": " +
                         without_option_prefix(e.what(), a.key));
      }
    }
  }
  // Then every combination, for the rules across keys (near < far, ...) and strategy parameters.
  // (The seed cannot make a scene invalid, since any whole number is a seed.)
  for (const auto& c : combos) {
    try {
      const Scene scene =
          parse_scene(plan.scene_text, plan.origin, sweep_overrides(plan, c, seeds.front()));
      for (const std::string& n : plan.strategies) validate_strategy_settings(n, scene);
    } catch (const SceneError& e) {
      throw UsageError("--vary " + describe_combination(plan, c) + ": " + e.what());
    } catch (const std::invalid_argument& e) {
      throw UsageError("--vary " + describe_combination(plan, c) + ": " + e.what());
    }
  }
  return command;
}

// The CSV, with a header, then per job (in plan order) one row per strategy.
std::string sweep_csv(const SweepPlan& plan, const std::vector<std::vector<Evaluation>>& results) {
  std::size_t seed_column = 0;
  std::string csv = join(sweep_columns(plan, seed_column)) + "\n";
  for (std::size_t j = 0; j < plan.jobs.size(); ++j) {
    const SweepJob& job = plan.jobs[j];
    // Parsed again here for the rows' scene-derived cells (the z-fighting flag), because it is the
    // scene the worker ran.
    const Scene scene =
        parse_scene(plan.scene_text, plan.origin, sweep_overrides(plan, job.value_index, job.seed));
    for (const Evaluation& e : results[j]) {
      std::vector<std::string> cells;
      for (std::size_t k = 0; k < plan.axes.size(); ++k) {
        cells.push_back(plan.axes[k].values[job.value_index[k]]);
      }
      cells.push_back(std::to_string(job.seed));
      const std::vector<std::string> summary = summary_csv_cells(scene, e.summary);
      for (std::size_t i = 0; i < summary.size(); ++i) {
        if (i != seed_column) cells.push_back(summary[i]);
      }
      csv += join(cells) + "\n";
    }
  }
  return csv;
}

void show_progress(std::size_t done, std::size_t total) {
  std::fprintf(stderr, "\r sweep: %zu/%zu runs", done, total);
  std::fflush(stderr);
}

// ---- The single-key summary. ----

void print_single_key_tables(const std::string& key, const std::string& csv, std::ostream& out) {
  const std::vector<SweepOutcome> rows = read_sweep_outcomes(csv, key);
  const std::vector<SweepStrategyStats> stats = summarise_single_key(rows);
  const bool numeric = sweep_values_numeric(rows);
  std::set<std::uint64_t> distinct_seeds;
  for (const SweepOutcome& o : rows) distinct_seeds.insert(o.seed);
  const std::size_t seeds = distinct_seeds.size();
  for (const SweepStrategyStats& st : stats) {
    out << "\n"
        << st.strategy << ": seeds with zero intersections (near-plane and camera) out of " << seeds
        << ", mean of dev_mean_m over the seeds\n";
    Table t({key, "zero_seeds", "dev_mean_m"});
    for (const SweepValueStats& v : st.values) {
      t.add_row({v.value, std::to_string(v.zero_seeds) + "/" + std::to_string(v.seeds),
                 fixed(v.deviation_mean_m, 4)});
    }
    t.print(out);
  }
  out << "\nsmallest " << key << " from which the strategy keeps zero intersections on every "
      << "seed, at that value and every " << (numeric ? "larger" : "later")
      << " value in the sweep, and its mean dev_mean_m there ('-': never)\n";
  Table t({"strategy", key, "dev_mean_m"});
  for (const SweepStrategyStats& st : stats) {
    if (st.threshold) {
      const SweepValueStats& v = st.values[*st.threshold];
      t.add_row({st.strategy, v.value, fixed(v.deviation_mean_m, 4)});
    } else {
      t.add_row({st.strategy, "-", "-"});
    }
  }
  t.print(out);
}

}  // namespace

int cmd_sweep(const std::vector<std::string>& args) {
  po::options_description own("sweep options");
  std::string all_names;
  for (const std::string& n : strategy_names()) all_names += (all_names.empty() ? "" : ",") + n;
  own.add_options()(
      "vary", po::value<std::vector<std::string>>()->composing()->value_name("KEY=SPEC"),
      "a scene key and its values: a list 1,2,5 (vectors '0 1.6 -5,0 1.6 -7') or a range "
      "lo:hi:step (numeric keys only); repeat for the cartesian product")(
      "seeds", po::value<long long>()->value_name("N"),
      "run seeds 1..N (default: the scene's own seed)")(
      "seed-list", po::value<std::string>()->value_name("a,b,c"), "run these seeds")(
      "strategies", po::value<std::string>()->default_value(all_names),
      "comma-separated strategies to compare on every combination")(
      "jobs", po::value<std::string>()->value_name("J"),
      "worker processes (default: the number of online CPUs)")(
      "out", po::value<std::string>()->value_name("FILE"), "the CSV file to write")(
      "force", "overwrite an existing FILE")(
      "no-occlusion", "skip the screen-occlusion raster (faster; occlusion columns read 0)")(
      "shard", po::value<std::string>()->value_name("K/N"),
      "run only slice K (from 0) of N of the jobs and write it with its plan's fingerprint; "
      "`fragsim merge` joins the N slices into the file the whole sweep writes");
  const ParsedCommand p = parse_command("sweep", args, own);
  if (p.help_shown) return 0;
  const SweepCommandPlan command = plan_sweep(p);
  // A slice runs its jobs alone; the fingerprint is the whole plan's, so slices of one plan match.
  std::string slice_head;
  SweepPlan sliced;
  if (command.shard) {
    std::size_t seed_column = 0;
    const std::string plan_id =
        sweep_plan_fingerprint(command.sweep, join(sweep_columns(command.sweep, seed_column)));
    sliced = command.sweep;
    const JobRange r = shard_range(command.sweep.jobs.size(), *command.shard);
    sliced.jobs.assign(command.sweep.jobs.begin() + static_cast<std::ptrdiff_t>(r.begin),
                       command.sweep.jobs.begin() + static_cast<std::ptrdiff_t>(r.end));
    sliced.first_job = r.begin;
    slice_head = plan_id;
  }
  const SweepPlan& plan = command.shard ? sliced : command.sweep;
  // Fails early, as a usage error, when the file cannot be written, by a probe through the same
  // temporary-file-and-rename path, removed again before the workers are forked.
  try {
    const AtomicFile probe(command.out);
  } catch (const std::runtime_error& e) {
    throw UsageError(std::string("--out ") + e.what());
  }

  const bool progress = ::isatty(STDERR_FILENO) == 1;
  if (progress) show_progress(0, plan.jobs.size());
  std::vector<std::vector<Evaluation>> results;
  try {
    results = run_sweep(plan, command.jobs, [&](std::size_t done) {
      if (progress) show_progress(done, plan.jobs.size());
    });
  } catch (...) {
    if (progress) std::fputc('\n', stderr);  // the error's line after the progress line, not on it
    throw;
  }
  if (progress) std::fputc('\n', stderr);
  const std::string csv = sweep_csv(plan, results);
  if (command.shard) {
    write_file_atomically(
        command.out,
        slice_line("sweep", *command.shard, slice_head, command.sweep.jobs.size(), csv) + csv);
    const JobRange r = shard_range(command.sweep.jobs.size(), *command.shard);
    std::cout << "wrote " << command.out << ": slice " << command.shard->index << "/"
              << command.shard->count << " of plan " << slice_head << ", jobs " << r.begin << "-"
              << r.end << " of " << command.sweep.jobs.size() << ", "
              << plan.jobs.size() * plan.strategies.size() << " rows (fragsim merge joins the "
              << command.shard->count << " slices)\n";
    return 0;
  }
  write_file_atomically(command.out, csv);
  std::cout << "wrote " << command.out << ": " << plan.jobs.size() * plan.strategies.size()
            << " rows (" << plan.jobs.size() << " runs x " << plan.strategies.size()
            << " strategies)\n";
  if (plan.axes.size() == 1) print_single_key_tables(plan.axes.front().key, csv, std::cout);
  return 0;
}

void print_sweep_tables(const std::string& csv, std::ostream& out) {
  // The varied keys are the columns before `seed`; the tables are for one.
  const std::string header = csv.substr(0, csv.find('\n'));
  const std::size_t seed = header.find(",seed,");
  if (seed == std::string::npos || header.find(',') != seed) return;
  print_single_key_tables(header.substr(0, seed), csv, out);
}

}  // namespace fragsim::cli
