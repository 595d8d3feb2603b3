// fragsim: the command line. It parses options into a scene, runs, prints; every failure becomes
// one line on stderr and a non-zero exit (2 for usage errors, 1 for failures while running).

#include <boost/program_options.hpp>
#include <exception>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "cli/table.hpp"
#include "metrics/evaluation.hpp"
#include "sim/scene_file.hpp"
#include "sim/world.hpp"
#include "strategies/registry.hpp"

namespace po = boost::program_options;
using namespace fragsim;

namespace {

constexpr int kUsageError = 2;

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

const char* kUsage =
    "usage: fragsim <command> [options]\n"
    "commands:\n"
    "  run      one strategy on a scene\n"
    "  compare  every strategy on the same scene and seed\n"
    "'fragsim <command> --help' lists a command's options and every scene key.\n";

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    if (!item.empty()) out.push_back(item);
  }
  return out;
}

struct Parsed {
  po::variables_map vm;
  Scene scene;
};

// Parses a command's own options plus every scene key; loads the scene.
Parsed parse(const std::string& command, const std::vector<std::string>& args,
             po::options_description own) {
  own.add_options()("scene", po::value<std::string>()->value_name("FILE"),
                    "scene file (INI); without it, the built-in defaults")(
      "help,h", "this help");
  po::options_description all;
  all.add(own).add(scene_options());
  po::parsed_options parsed(nullptr);
  try {
    parsed = po::command_line_parser(args).options(all).run();
  } catch (const po::error& e) {
    throw UsageError(e.what());
  }
  Parsed p;
  po::store(parsed, p.vm);
  if (p.vm.count("help")) {
    std::cout << "usage: fragsim " << command << " [options]\n" << all << '\n';
    std::exit(0);
  }
  try {
    p.scene = load_scene(p.vm.count("scene") ? p.vm["scene"].as<std::string>() : "",
                         scene_overrides(parsed));
  } catch (const SceneError& e) {
    throw UsageError(e.what());
  }
  return p;
}

void print_table(const std::vector<Evaluation>& runs, std::ostream& out) {
  cli::Table table({"strategy", "near_frag", "near_steps", "cam_hits", "cand_t0", "cand_max",
                    "forced", "impulse_Ns", "max_a_mps2", "capped", "wall_hits", "near_min_m",
                    "phys_ms", "strat_ms", "run_s"});
  for (const Evaluation& e : runs) {
    const RunSummary& s = e.summary;
    table.add_row({s.strategy, std::to_string(s.near_fragments),
                   std::to_string(s.near_fragment_steps), std::to_string(s.camera_hit_fragments),
                   std::to_string(s.candidates_initial), std::to_string(s.candidates_max),
                   std::to_string(s.forced_fragments), cli::fixed(s.impulse_Ns, 3),
                   cli::fixed(s.max_accel_mps2, 1), std::to_string(s.capped_forces),
                   std::to_string(s.wall_contacts), cli::fixed(s.min_near_m, 3),
                   cli::fixed(s.physics_ms_median, 3), cli::fixed(s.strategy_ms_median, 3),
                   cli::fixed(s.wall_s, 3)});
  }
  table.print(out);
}

void print_header(const Scene& scene, std::ostream& out) {
  out << "scene " << scene.name << ": " << scene.fragment_count() << " fragments, "
      << scene.step_count() << " steps of " << cli::fixed(scene.sim.dt_s, 5) << " s, seed "
      << scene.sim.seed << ", ODE " << World::ode_version() << "\n";
}

int cmd_run(const std::vector<std::string>& args) {
  po::options_description own("run options");
  own.add_options()("strategy", po::value<std::string>()->default_value("edge"),
                    "none | wall | deflect-all | near-plane | edge");
  Parsed p = parse("run", args, own);
  const std::string name = p.vm["strategy"].as<std::string>();
  std::vector<Evaluation> runs;
  try {
    runs.push_back(evaluate(p.scene, name));
  } catch (const std::invalid_argument& e) {
    throw UsageError(std::string("--strategy: ") + e.what());
  }
  print_header(p.scene, std::cout);
  print_table(runs, std::cout);
  return 0;
}

int cmd_compare(const std::vector<std::string>& args) {
  po::options_description own("compare options");
  std::string all_names;
  for (const std::string& n : strategy_names()) all_names += (all_names.empty() ? "" : ",") + n;
  own.add_options()("strategies", po::value<std::string>()->default_value(all_names),
                    "comma-separated strategies to compare");
  Parsed p = parse("compare", args, own);
  const std::vector<std::string> names = split_list(p.vm["strategies"].as<std::string>());
  if (names.empty()) throw UsageError("--strategies: no strategy named");
  // Every name is checked before anything runs.
  for (const std::string& n : names) {
    try {
      make_strategy(n, p.scene);
    } catch (const std::invalid_argument& e) {
      throw UsageError(std::string("--strategies: ") + e.what());
    }
  }
  std::vector<Evaluation> runs;
  for (const std::string& n : names) runs.push_back(evaluate(p.scene, n));
  print_header(p.scene, std::cout);
  print_table(runs, std::cout);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << kUsage;
    return kUsageError;
  }
  const std::string command = argv[1];
  const std::vector<std::string> args(argv + 2, argv + argc);
  try {
    if (command == "run") return cmd_run(args);
    if (command == "compare") return cmd_compare(args);
    if (command == "--help" || command == "-h" || command == "help") {
      std::cout << kUsage;
      return 0;
    }
    std::cerr << "fragsim: unknown command '" << command << "'\n" << kUsage;
    return kUsageError;
  } catch (const UsageError& e) {
    std::cerr << "fragsim " << command << ": " << e.what() << '\n';
    return kUsageError;
  } catch (const std::exception& e) {
    std::cerr << "fragsim " << command << ": " << e.what() << '\n';
    return 1;
  }
}
