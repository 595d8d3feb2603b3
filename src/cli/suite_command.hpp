#pragma once
// `fragsim suite`: the fixed battery of experiments/suite.hpp (many scenes, cameras and seeds),
// every strategy on every run; one table per camera mode, the recommendation, and a tidy CSV.

#include <string>
#include <vector>

namespace fragsim::cli {

// Parses and validates everything (UsageError, before any simulation runs), runs the battery on
// worker processes, prints the tables and writes --out. Returns the exit status.
int cmd_suite(const std::vector<std::string>& args);

}  // namespace fragsim::cli
