#pragma once
// `fragsim sweep` varies scene keys over values and seeds, compares each combination in a worker
// process, and merges all rows into one CSV in a fixed order.

#include <ostream>
#include <string>
#include <vector>

namespace fragsim::cli {

// Parses and validates everything, runs the jobs (experiments/sweep.hpp's run_sweep), writes
// their rows into --out and, when one key is varied, prints the per-value tables. Returns the
// exit status; throws UsageError for bad input (before any simulation runs), TaskFailed when a
// job fails and Interrupted on a stop signal.
int cmd_sweep(const std::vector<std::string>& args);

// The per-value tables `cmd_sweep` prints when one key is varied, from a sweep CSV alone (a merged
// one from `fragsim merge`); nothing when the CSV varies more than one key.
void print_sweep_tables(const std::string& csv, std::ostream& out);

}  // namespace fragsim::cli
