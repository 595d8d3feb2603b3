#pragma once
// `fragsim sweep`: scene keys varied over values and seeds, each combination compared in a worker
// process, all rows merged into one CSV in a fixed order.

#include <string>
#include <vector>

namespace fragsim::cli {

// Parses and validates everything, forks the workers, merges their rows into --out and, when one
// key is varied, prints the per-value tables. Returns the exit status; throws UsageError for bad
// input (before any simulation runs) and std::runtime_error when a worker fails.
int cmd_sweep(const std::vector<std::string>& args);

}  // namespace fragsim::cli
