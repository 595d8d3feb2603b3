#pragma once
// `fragsim bench` measures run time against error on one scene and strategy
// (experiments/time_vs_error.hpp), printed as a table with the Pareto front marked, and written as
// CSV for data/plots/pareto.gp.

#include <string>
#include <vector>

namespace fragsim::cli {

// Returns the exit status; throws UsageError for bad input before any simulation runs.
int cmd_bench(const std::vector<std::string>& args);

}  // namespace fragsim::cli
