#pragma once
// `fragsim run` runs one strategy on a scene, compared with `none` as the deviation reference, or,
// with --dump-control, the strategy alone, recording what it was given and applied each step.

#include <string>
#include <vector>

namespace fragsim::cli {

// Returns the exit status; throws UsageError for bad input and Interrupted on a stop signal.
int cmd_run(const std::vector<std::string>& args);

}  // namespace fragsim::cli
