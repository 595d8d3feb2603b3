#pragma once
// `fragsim merge OUT SLICE...` joins the slices that `fragsim sweep --shard K/N` or
// `fragsim suite --shard K/N` wrote (one per task of a job array) into OUT, the file the unsharded
// command writes, byte for byte (experiments/shard.hpp).

#include <string>
#include <vector>

namespace fragsim::cli {

// Reads every slice, refuses a set that cannot be merged (one line naming the file), writes OUT
// whole or not at all. Returns the exit status; throws UsageError for bad input.
int cmd_merge(const std::vector<std::string>& args);

}  // namespace fragsim::cli
