#include "cli/merge_command.hpp"

#include <boost/program_options.hpp>
#include <filesystem>
#include <iostream>

#include "cli/command_line.hpp"
#include "cli/suite_command.hpp"
#include "cli/sweep_command.hpp"
#include "experiments/shard.hpp"
#include "io/atomic_file.hpp"
#include "io/input_file.hpp"

namespace fragsim::cli {
namespace {

namespace po = boost::program_options;
namespace fs = std::filesystem;

const char* kMergeUsage =
    "usage: fragsim merge [--force] OUT SLICE...\n"
    "Joins the slices written by `fragsim sweep --shard K/N` or `fragsim suite --shard K/N` into "
    "OUT, byte for byte the file the unsharded command writes. Refuses slices of different plans, "
    "a slice given twice and missing slices. Then prints the tables the unsharded command prints "
    "(a suite's per mode and its recommendation; a sweep's per value when it varies one key).\n";

}  // namespace

int cmd_merge(const std::vector<std::string>& args) {
  po::options_description own("merge options");
  own.add_options()("force", "overwrite an existing OUT")("help,h", "this help")(
      "files", po::value<std::vector<std::string>>()->composing(), "OUT then the slices");
  po::positional_options_description positional;
  positional.add("files", -1);
  po::variables_map vm;
  try {
    po::store(po::command_line_parser(args).options(own).positional(positional).run(), vm);
  } catch (const po::error& e) {
    throw UsageError(e.what());
  }
  if (vm.count("help")) {
    std::cout << kMergeUsage << "  --force    overwrite an existing OUT\n";
    return 0;
  }
  const std::vector<std::string> files =
      vm.count("files") ? vm["files"].as<std::vector<std::string>>() : std::vector<std::string>{};
  if (files.size() < 2) throw UsageError("expected OUT and at least one SLICE file");
  const std::string& out = files.front();
  if (out.empty()) throw UsageError("OUT: empty file name");
  std::error_code ec;
  if (fs::is_directory(out, ec)) throw UsageError(out + ": is a folder");
  std::vector<SliceFile> slices;
  for (std::size_t i = 1; i < files.size(); ++i) {
    if (fs::exists(out, ec) && fs::exists(files[i], ec) && fs::equivalent(out, files[i], ec)) {
      throw UsageError(out + ": is also given as a slice (OUT comes first)");
    }
    try {
      slices.push_back({files[i], read_text_file(files[i], "slice file")});
    } catch (const InputError& e) {
      throw UsageError(e.what());
    }
  }
  if (fs::exists(out, ec) && !vm.count("force")) {
    throw UsageError(out + ": exists (use --force to overwrite)");
  }
  std::string merged, command;
  try {
    merged = merge_slices(slices, &command);
  } catch (const ShardError& e) {
    throw UsageError(e.what());
  }
  write_file_atomically(out, merged);
  std::size_t rows = 0;
  for (char c : merged) rows += c == '\n';
  std::cout << "wrote " << out << ": " << (rows > 0 ? rows - 1 : 0) << " rows from "
            << slices.size() << " slices\n";
  // The tables the unsharded command prints, from the merged rows.
  if (command == "suite") {
    const SuiteTable t = read_suite_csv(merged);
    std::cout << "\n";
    print_suite_tables(t.runs, t.outcomes, t.variants, std::cout);
  } else {
    print_sweep_tables(merged, std::cout);
  }
  return 0;
}

}  // namespace fragsim::cli
