#pragma once
// `fragsim play` lets you fly the camera yourself (src/play). This file only parses the options,
// opens the window or the benchmark's script, and prints each flight's numbers and replay command.

#include <string>
#include <vector>

namespace fragsim::cli {

// Returns the exit status; throws UsageError for bad input and for no display (one line, 2).
int cmd_play(const std::vector<std::string>& args);

}  // namespace fragsim::cli
