#pragma once
// What every subcommand shares, its options plus every scene key, parsed into a scene.

#include <boost/program_options.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "sim/scene.hpp"

namespace fragsim::cli {

// A usage error, printed as one line, with exit status 2.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct ParsedCommand {
  boost::program_options::variables_map options;
  Scene scene;
  bool help_shown = false;
};

// Parses `args` with the command's own options, --scene, --help and every scene key, and loads the
// scene. Prints the help and sets help_shown when asked; prints the scene's warnings (a track that
// does not cover the run, a key without effect) on stderr, one "warning: " line each. Throws
// UsageError.
ParsedCommand parse_command(const std::string& command, const std::vector<std::string>& args,
                            boost::program_options::options_description own);

std::vector<std::string> split_list(const std::string& text);

// The worker processes --jobs asks for (a text option, so that every bad value gets the same one
// line), or one per online CPU without it. Throws UsageError naming --jobs.
int jobs_option(const boost::program_options::variables_map& options);

}  // namespace fragsim::cli
