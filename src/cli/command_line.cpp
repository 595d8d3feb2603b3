#include "cli/command_line.hpp"

#include <iostream>
#include <sstream>

#include "experiments/process_runner.hpp"
#include "sim/scene_file.hpp"

namespace fragsim::cli {
namespace po = boost::program_options;

ParsedCommand parse_command(const std::string& command, const std::vector<std::string>& args,
                            po::options_description own) {
  own.add_options()("scene", po::value<std::string>()->value_name("FILE"),
                    "scene file (INI); without it, the built-in defaults")("help,h", "this help");
  po::options_description all;
  all.add(own).add(scene_options());
  ParsedCommand p;
  po::parsed_options parsed(nullptr);
  try {
    parsed = po::command_line_parser(args).options(all).run();
    po::store(parsed, p.options);
  } catch (const po::error& e) {
    throw UsageError(e.what());
  }
  if (p.options.count("help")) {
    std::cout << "usage: fragsim " << command << " [options]\n"
              << all << '\n'
              << describe_strategies(strategy_table()) << '\n';
    p.help_shown = true;
    return p;
  }
  std::vector<std::string> warnings;
  try {
    p.scene = load_scene(p.options.count("scene") ? p.options["scene"].as<std::string>() : "",
                         scene_overrides(parsed), &warnings);
  } catch (const SceneError& e) {
    throw UsageError(e.what());
  }
  for (const std::string& w : warnings) std::cerr << "warning: " << w << '\n';
  return p;
}

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ',')) {
    if (!item.empty()) out.push_back(item);
  }
  return out;
}

int jobs_option(const po::variables_map& options) {
  if (!options.count("jobs")) return online_cpus();
  try {
    return parse_jobs(options["jobs"].as<std::string>());
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
}

}  // namespace fragsim::cli
