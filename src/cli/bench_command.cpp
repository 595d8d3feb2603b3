#include "cli/bench_command.hpp"

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <set>

#include "cli/command_line.hpp"
#include "cli/table.hpp"
#include "experiments/time_vs_error.hpp"
#include "io/atomic_file.hpp"
#include "sim/scene_strategies.hpp"

namespace fragsim::cli {
namespace {

namespace po = boost::program_options;

// "NAME:key=value;key=value" -> a custom configuration.
BenchConfig parse_config(const std::string& text) {
  const std::size_t colon = text.find(':');
  if (colon == std::string::npos || colon == 0) {
    throw UsageError("--config " + text + ": expected NAME:key=value;key=value");
  }
  BenchConfig c{text.substr(0, colon), "custom", {}};
  std::size_t start = colon + 1;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find(';', start), text.size());
    const std::string item = text.substr(start, end - start);
    const std::size_t eq = item.find('=');
    if (eq == std::string::npos || eq == 0) {
      throw UsageError("--config " + text + ": '" + item + "' is not key=value");
    }
    c.overrides.push_back({item.substr(0, eq), item.substr(eq + 1)});
    start = end + 1;
  }
  return c;
}

std::string sci(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2e", v);
  return buf;
}

std::string with_difference(int value, int difference) {
  return std::to_string(value) + (difference != 0 ? " (" + std::to_string(difference) + ")" : "");
}

void print_rows(const std::vector<BenchRow>& rows, std::ostream& out) {
  Table t({"config", "dt_s", "compute_s_per_sim_s", "physics_ms", "strategy_ms",
           "flight_err_mean_m", "flight_err_max_m", "pos_err_mean_m", "near (diff)", "hits (diff)",
           "cand_diff", "pred_err_mean_m", "pareto"});
  for (const BenchRow& r : rows) {
    t.add_row({r.config.name, sci(r.dt_s), fixed(r.compute_s_per_sim_s, 4),
               fixed(r.physics_ms_per_step, 3), fixed(r.strategy_ms_per_step, 3),
               sci(r.flight_error_mean_m), sci(r.flight_error_max_m), sci(r.position_error_mean_m),
               with_difference(r.near_fragments, r.near_difference),
               with_difference(r.camera_hit_fragments, r.camera_hit_difference),
               std::to_string(r.candidate_difference), sci(r.prediction_error_mean_m),
               r.pareto ? "*" : ""});
  }
  t.print(out);
}

// Where the scene's own configuration stands, with its speed-up over the reference, its errors, and
// the faster configurations that pay for their speed in error.
void print_default_verdict(const std::vector<BenchRow>& rows, std::ostream& out) {
  const BenchRow& ref = rows.front();
  const BenchRow* def = nullptr;
  for (const BenchRow& r : rows) {
    if (r.config.group == "default") def = &r;
  }
  if (def == nullptr) return;
  out << "\nthe scene as given ('default'): "
      << fixed(ref.compute_s_per_sim_s / def->compute_s_per_sim_s, 1)
      << "x faster than the reference, mean flight error " << sci(def->flight_error_mean_m)
      << " m, near-plane fragments " << def->near_fragments << " vs " << ref.near_fragments
      << ", camera hits " << def->camera_hit_fragments << " vs " << ref.camera_hit_fragments
      << (def->pareto ? "; on the Pareto front" : "; not on the Pareto front") << "\n";
  for (const BenchRow& r : rows) {
    if (&r == def || r.compute_s_per_sim_s >= def->compute_s_per_sim_s) continue;
    out << "  faster: " << r.config.name << " ("
        << fixed(def->compute_s_per_sim_s / r.compute_s_per_sim_s, 2) << "x), flight error "
        << sci(r.flight_error_mean_m) << " m, near-plane fragments " << r.near_fragments
        << ", camera hits " << r.camera_hit_fragments << "\n";
  }
}

}  // namespace

int cmd_bench(const std::vector<std::string>& args) {
  po::options_description own("bench options");
  own.add_options()("strategy", po::value<std::string>()->default_value("edge"),
                    "the strategy run under every configuration")(
      "groups", po::value<std::string>()->value_name("LIST"),
      "only these configuration groups: dt,solver,predictor,replan,skip (default: all)")(
      "config", po::value<std::vector<std::string>>()->composing()->value_name("NAME:K=V;K=V"),
      "an extra configuration: scene keys set on top of the scene (repeatable)")(
      "repeats", po::value<int>()->default_value(3)->value_name("N"),
      "timed runs per configuration; the median is reported")(
      "out", po::value<std::string>()->value_name("FILE"), "write the rows as CSV")(
      "force", "overwrite an existing FILE");
  const ParsedCommand p = parse_command("bench", args, own);
  if (p.help_shown) return 0;

  TimeVsErrorOptions options;
  options.strategy = p.options["strategy"].as<std::string>();
  try {
    validate_strategy_settings(options.strategy, p.scene);
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--strategy: ") + e.what());
  }
  options.repeats = p.options["repeats"].as<int>();
  if (options.repeats < 1 || options.repeats > 100) {
    throw UsageError("--repeats " + std::to_string(options.repeats) + ": must be in [1, 100]");
  }

  std::vector<BenchConfig> configs = standard_bench_configs(options.strategy);
  if (p.options.count("groups")) {
    const std::vector<std::string> wanted = split_list(p.options["groups"].as<std::string>());
    std::set<std::string> known;
    for (const BenchConfig& c : configs) known.insert(c.group);
    for (const std::string& g : wanted) {
      if (!known.count(g)) throw UsageError("--groups: no group '" + g + "' for this strategy");
    }
    std::erase_if(configs, [&](const BenchConfig& c) {
      return c.group != "default" &&
             std::find(wanted.begin(), wanted.end(), c.group) == wanted.end();
    });
  }
  if (p.options.count("config")) {
    for (const std::string& text : p.options["config"].as<std::vector<std::string>>()) {
      configs.push_back(parse_config(text));
    }
  }

  std::optional<AtomicFile> file;
  if (p.options.count("out")) {
    const std::string path = p.options["out"].as<std::string>();
    if (path.empty()) throw UsageError("--out: empty file name");
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
      throw UsageError("--out " + path + ": is a folder");
    if (std::filesystem::exists(path, ec) && !p.options.count("force")) {
      throw UsageError("--out " + path + ": exists (use --force to overwrite)");
    }
    try {
      file.emplace(path);  // fails here, not after minutes of running, if the folder is unwritable
    } catch (const std::runtime_error& e) {
      throw UsageError(std::string("--out: ") + e.what());
    }
  }

  std::cout << "bench: scene " << p.scene.name << ", strategy " << options.strategy << ", "
            << p.scene.fragment_count() << " fragments, " << options.repeats
            << " timed runs per configuration; reference = "
            << "dt 1/480 s with the exact solver\n";
  std::vector<BenchRow> rows;
  std::vector<BenchDuplicate> duplicates;
  try {
    rows = run_time_vs_error(
        p.scene, configs, reference_bench_config(), options,
        [](const BenchRow& r) { std::cerr << "bench: ran " << r.config.name << "\n"; },
        &duplicates);
  } catch (const SceneError& e) {
    throw UsageError(e.what());
  }
  print_rows(rows, std::cout);
  for (const BenchDuplicate& d : duplicates) {
    std::cout << "(" << d.name << ": the same simulation as " << d.same_as << ", not run again)\n";
  }
  print_default_verdict(rows, std::cout);
  if (file) {
    write_time_vs_error_csv(file->out(), rows);
    file->commit();
    std::cout << "wrote " << file->path() << "\n";
  }
  return 0;
}

}  // namespace fragsim::cli
