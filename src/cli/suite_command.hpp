#pragma once
// `fragsim suite` runs the fixed battery of experiments/suite.hpp (many scenes, cameras and seeds),
// every strategy on every run, and prints one table per camera mode, the recommendation, a tidy
// CSV.

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

#include "experiments/suite.hpp"

namespace fragsim::cli {

// Parses and validates everything (UsageError, before any simulation runs), runs the battery on
// worker processes, prints the tables and writes --out. Returns the exit status.
int cmd_suite(const std::vector<std::string>& args);

// The tables and the recommendation cmd_suite prints, for `runs` and their `outcomes` (run order,
// then variant order) with `variants` rows per run; `fragsim merge` prints them for a merged
// suite from the CSV (read_suite_csv).
void print_suite_tables(const std::vector<SuiteRun>& runs,
                        const std::vector<SuiteOutcome>& outcomes, std::size_t variants,
                        std::ostream& out);

}  // namespace fragsim::cli
