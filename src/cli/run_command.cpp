#include "cli/run_command.hpp"

#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "cli/command_line.hpp"
#include "cli/compare_command.hpp"
#include "experiments/control_dump.hpp"
#include "experiments/evaluation.hpp"
#include "io/input_error.hpp"
#include "sim/scene_strategies.hpp"
#include "strategies/registry.hpp"

namespace fragsim::cli {

namespace po = boost::program_options;

namespace {

// `run --dump-control FILE` records the strategy alone (no reference run, no metrics output).
int dump_control(const cli::ParsedCommand& p, const std::string& strategy) {
  for (const char* other : {"csv", "trajectories", "report", "sheet", "bake"}) {
    if (p.options.count(other)) {
      throw UsageError(std::string("--dump-control: runs the strategy alone; not with --") + other);
    }
  }
  const std::string path = p.options["dump-control"].as<std::string>();
  if (path.empty()) throw UsageError("--dump-control: empty file name");
  if (!ControlDump::supports(strategy)) {
    throw UsageError("--dump-control: strategy '" + strategy +
                     "' is not in the controller library (edge-min, edge, deflect-all)");
  }
  std::error_code ec;
  if (std::filesystem::exists(path, ec) && !p.options.count("force")) {
    throw UsageError("--dump-control " + path + ": exists (use --force to overwrite)");
  }
  try {
    validate_strategy_settings(strategy, p.scene);
  } catch (const InputError& e) {
    throw UsageError(std::string("--strategy: ") + e.what());
  }
  ControlDump dump(path, strategy, p.scene);
  EvaluationOptions options;
  options.occlusion = false;
  options.control_dump = &dump;
  evaluate(p.scene, strategy, options);
  dump.commit();
  std::cout << "wrote " << path << ": " << dump.steps() << " steps of " << strategy << ", "
            << p.scene.fragment_count() << " fragments\n";
  return 0;
}

}  // namespace

int cmd_run(const std::vector<std::string>& args) {
  po::options_description own("run options");
  const std::string names = join_strategy_names(strategy_table(), " | ");
  own.add_options()("strategy", po::value<std::string>()->default_value("edge"), names.c_str());
  add_output_options(own);
  own.add_options()("dump-control", po::value<std::string>()->value_name("FILE"),
                    "only run the strategy (edge-min, edge or deflect-all) and write, per step, "
                    "the inputs it got and the forces applied to FILE (binary, "
                    "src/experiments/control_dump.hpp), for the controller library's replay test");
  const cli::ParsedCommand p = cli::parse_command("run", args, own);
  if (p.help_shown) return 0;
  const std::string strategy = p.options["strategy"].as<std::string>();
  if (p.options.count("dump-control")) return dump_control(p, strategy);
  return run_and_report(p, {strategy});
}

}  // namespace fragsim::cli
