#pragma once
// `fragsim compare` runs every chosen strategy on the same scene and seed, prints the table, and
// writes the outputs asked for (CSV files, the HTML report, bakes, a contact sheet). `run` is the
// same with one strategy.

#include <boost/program_options.hpp>
#include <string>
#include <vector>

#include "cli/command_line.hpp"

namespace fragsim::cli {

// Parses and validates everything, runs the strategies and prints the comparison. Returns the exit
// status; throws UsageError for bad input, TaskFailed when a worker fails and Interrupted on a
// stop signal.
int cmd_compare(const std::vector<std::string>& args);

// The options of a run's outputs, shared by `run` and `compare`: --csv, --trajectories, --report,
// --force, --no-occlusion, --jobs, --bake, --bake-max-mb and the contact sheet's.
void add_output_options(boost::program_options::options_description& own);

// Runs `names` on the parsed scene, prints the table and writes the outputs `p` asks for, each
// output whole or not at all. Returns the exit status.
int run_and_report(const ParsedCommand& p, const std::vector<std::string>& names);

}  // namespace fragsim::cli
