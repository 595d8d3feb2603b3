#include "cli/suite_command.hpp"

#include <unistd.h>

#include <boost/program_options.hpp>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

#include "cli/command_line.hpp"
#include "cli/table.hpp"
#include "experiments/shard.hpp"
#include "experiments/suite.hpp"
#include "io/atomic_file.hpp"

namespace fragsim::cli {
namespace {

namespace po = boost::program_options;
namespace fs = std::filesystem;

std::string percent(double share) {
  return fixed(100.0 * share, 1);
}

std::string join(const std::vector<std::string>& items, const std::string& sep) {
  std::string s;
  for (const std::string& i : items) s += (s.empty() ? "" : sep) + i;
  return s;
}

void print_rows(const std::vector<SuiteRow>& rows, std::ostream& out) {
  Table t({"strategy", "runs", "clean_%", "dev_mean_m", "misses_kept_%", "strat_ms"});
  for (const SuiteRow& r : rows) {
    const std::optional<double> kept = r.near_misses_kept();
    t.add_row({r.variant, std::to_string(r.runs), percent(r.clean_share()),
               fixed(r.deviation_mean_m, 4), kept ? percent(*kept) : "-",
               fixed(r.strategy_ms_median, 4)});
  }
  t.print(out);
}

// Fails early, as a usage error, when FILE cannot be written, by a probe through the same
// temporary-file-and-rename path, removed again before the workers are forked.
void check_out(const std::string& path, bool force) {
  if (path.empty()) throw UsageError("--out: empty file name");
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw UsageError("--out " + path + ": is a folder");
  if (fs::exists(path, ec) && !force) {
    throw UsageError("--out " + path + ": exists (use --force to overwrite)");
  }
  try {
    const AtomicFile probe(path);
  } catch (const std::runtime_error& e) {
    throw UsageError(std::string("--out ") + e.what());
  }
}

// For --shard, the slice's runs alone, written after the slice line of the whole plan.
int run_suite_slice(const std::map<std::string, std::string>& scenes,
                    const std::vector<SuiteRun>& runs, const std::vector<SuiteVariant>& variants,
                    const Shard& shard, int jobs, const std::string& out_path) {
  const std::string plan = suite_plan_fingerprint(scenes, runs, variants);
  const JobRange r = shard_range(runs.size(), shard);
  const std::vector<SuiteRun> slice(runs.begin() + static_cast<std::ptrdiff_t>(r.begin),
                                    runs.begin() + static_cast<std::ptrdiff_t>(r.end));
  const bool progress = ::isatty(STDERR_FILENO) == 1;
  const std::vector<SuiteOutcome> outcomes =
      run_suite(scenes, slice, variants, jobs, [&](std::size_t done) {
        if (progress) std::fprintf(stderr, "\rsuite: %zu/%zu runs", done, slice.size());
      });
  if (progress) std::fputc('\n', stderr);
  const std::string csv = suite_csv(slice, outcomes);
  write_file_atomically(out_path, slice_line("suite", shard, plan, runs.size(), csv) + csv);
  std::cout << "wrote " << out_path << ": slice " << shard.index << "/" << shard.count
            << " of plan " << plan << ", runs " << r.begin << "-" << r.end << " of " << runs.size()
            << ", " << outcomes.size() << " rows (fragsim merge joins the " << shard.count
            << " slices)\n";
  return 0;
}

}  // namespace

void print_suite_tables(const std::vector<SuiteRun>& runs,
                        const std::vector<SuiteOutcome>& outcomes, std::size_t variants,
                        std::ostream& out) {
  out << "suite: " << runs.size() << " runs, " << variants
      << " strategy rows each (none first, the deviation reference)\n";
  for (const SuiteMode& mode : suite_modes()) {
    const auto in_mode = [&](std::size_t r) { return runs[r].mode == mode.name; };
    const std::vector<SuiteRow> rows = aggregate_suite(outcomes, in_mode);
    if (rows.empty()) continue;
    std::vector<std::string> keys;
    for (const SceneOverride& o : mode.overrides) keys.push_back(o.key + " = " + o.value);
    out << "\nmode " << mode.name << " (" << join(keys, ", ") << "): " << rows.front().runs
        << " runs\n";
    print_rows(rows, out);
  }
  out << "\nclean: zero near-plane fragments, camera hits and vanished fragments; "
         "dev_mean_m: mean over runs of each run's mean deviation from none;\nmisses_kept: "
         "the strategy's near "
         "misses over none's, summed over the runs; strat_ms: median over runs of the "
         "median strategy ms per step.\n";
  const std::vector<SuiteRow> player =
      aggregate_suite(outcomes, [&](std::size_t r) { return is_player_mode(runs[r].mode); });
  const std::vector<SuiteRow> all = aggregate_suite(outcomes);
  const std::optional<SuiteRecommendation> best = recommend_suite(player, all);
  out << "most robust (highest clean share over the player runs, then over all runs, then "
         "least mean deviation): ";
  if (best) {
    out << best->variant << " (";
    if (best->player_clean_share) {
      out << "clean in " << percent(*best->player_clean_share) << "% of player runs, ";
    } else {
      out << "no player run selected; clean in ";
    }
    out << percent(best->all_clean_share) << "% of all runs, mean deviation "
        << fixed(best->deviation_mean_m, 4) << " m)\n";
  } else {
    out << "-\n";
  }
}

int cmd_suite(const std::vector<std::string>& args) {
  std::string mode_names, scene_names;
  for (const SuiteMode& m : suite_modes()) mode_names += (mode_names.empty() ? "" : ",") + m.name;
  for (const SuiteSceneSpec& s : suite_scene_specs()) {
    scene_names += (scene_names.empty() ? "" : ",") + s.scene;
  }
  const std::string full = std::to_string(suite_runs({}).size());
  po::options_description own("suite options");
  own.add_options()("seeds", po::value<int>()->default_value(kSuiteDefaultSeeds)->value_name("N"),
                    ("seeds 1..N for every battery entry and camera mode (the default gives the "
                     "full battery of " +
                     full + " runs)")
                        .c_str())(
      "scenes", po::value<std::string>()->value_name("a,b"),
      ("only these battery scenes (default: " + scene_names + ")").c_str())(
      "modes", po::value<std::string>()->value_name("a,b"),
      ("only these camera modes (default: " + mode_names + ")").c_str())(
      "limit", po::value<long long>()->value_name("N"),
      "only the first N runs of the selection, in battery order (a CI slice)")(
      "scene-dir", po::value<std::string>()->default_value("data/scenes")->value_name("DIR"),
      "where the battery's scene files are")(
      "jobs", po::value<std::string>()->value_name("J"),
      "worker processes (default: the number of online CPUs)")(
      "out", po::value<std::string>()->value_name("FILE"),
      "write the tidy CSV, one row per run and strategy")("force", "overwrite an existing FILE")(
      "shard", po::value<std::string>()->value_name("K/N"),
      "run only slice K (from 0) of N of the runs and write it to --out with its plan's "
      "fingerprint, no tables; `fragsim merge` joins the N slices into the file the whole suite "
      "writes")("help,h", "this help");
  po::variables_map vm;
  try {
    const po::parsed_options parsed = po::command_line_parser(args).options(own).run();
    // Without this a stray word (`fragsim suite front`) would silently start the whole battery.
    const std::vector<std::string> extra =
        po::collect_unrecognized(parsed.options, po::include_positional);
    if (!extra.empty()) throw UsageError("unexpected argument '" + extra.front() + "'");
    po::store(parsed, vm);
  } catch (const po::error& e) {
    throw UsageError(e.what());
  }
  if (vm.count("help")) {
    std::cout
        << "usage: fragsim suite [options]\n"
        << "Runs every strategy on a fixed battery of scenes, explosion distances, aims and "
           "speeds, seeds and camera modes (docs/guide.md, Suite), and prints one table per mode "
           "and the most robust strategy.\n"
        << own << '\n';
    return 0;
  }

  SuiteSelection sel;
  sel.seeds = vm["seeds"].as<int>();
  if (vm.count("scenes")) {
    sel.scenes = split_list(vm["scenes"].as<std::string>());
    if (sel.scenes.empty()) throw UsageError("--scenes: no scene named");
  }
  if (vm.count("modes")) {
    sel.modes = split_list(vm["modes"].as<std::string>());
    if (sel.modes.empty()) throw UsageError("--modes: no mode named");
  }
  if (vm.count("limit")) {
    const long long limit = vm["limit"].as<long long>();
    if (limit < 1) throw UsageError("--limit " + std::to_string(limit) + ": must be >= 1");
    sel.limit = static_cast<std::size_t>(limit);
  }
  std::vector<SuiteRun> runs;
  try {
    runs = suite_runs(sel);
  } catch (const SuiteError& e) {
    // suite_runs checks the seeds first, then the scenes, then the modes.
    const std::string what = e.what();
    const char* option = what.find("battery scene") != std::string::npos  ? "--scenes: "
                         : what.find("battery mode") != std::string::npos ? "--modes: "
                                                                          : "--seeds: ";
    throw UsageError(option + what);
  }
  const int jobs = jobs_option(vm);
  std::optional<Shard> shard;
  if (vm.count("shard")) {
    try {
      shard = parse_shard(vm["shard"].as<std::string>());
    } catch (const ShardError& e) {
      throw UsageError(std::string("--shard ") + e.what());
    }
    if (!vm.count("out")) throw UsageError("--shard: needs --out FILE for the slice");
  }
  std::optional<std::string> out_path;
  if (vm.count("out")) {
    out_path = vm["out"].as<std::string>();
    check_out(*out_path, vm.count("force") > 0);
  }
  const std::string dir = vm["scene-dir"].as<std::string>();
  const std::vector<SuiteVariant> variants = suite_variants();
  std::map<std::string, std::string> scenes;
  try {
    scenes = load_suite_scenes(dir, runs);
    validate_suite(scenes, runs, variants);
  } catch (const SuiteError& e) {
    throw UsageError("--scene-dir " + dir + ": " + e.what());
  } catch (const SceneError& e) {
    throw UsageError("--scene-dir " + dir + ": " + e.what());
  } catch (const std::invalid_argument& e) {
    throw UsageError("--scene-dir " + dir + ": " + e.what());
  }

  if (shard) return run_suite_slice(scenes, runs, variants, *shard, jobs, *out_path);

  const bool progress = ::isatty(STDERR_FILENO) == 1;
  const std::vector<SuiteOutcome> outcomes =
      run_suite(scenes, runs, variants, jobs, [&](std::size_t done) {
        if (progress) std::fprintf(stderr, "\rsuite: %zu/%zu runs", done, runs.size());
      });
  if (progress) std::fputc('\n', stderr);

  print_suite_tables(runs, outcomes, variants.size(), std::cout);
  if (out_path) {
    write_file_atomically(*out_path, suite_csv(runs, outcomes));
    std::cout << "wrote " << *out_path << ": " << outcomes.size() << " rows (" << runs.size()
              << " runs x " << variants.size() << " strategies)\n";
  }
  return 0;
}

}  // namespace fragsim::cli
