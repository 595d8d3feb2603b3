// The fragsim command line. It parses options into a scene, runs, prints; every failure becomes one
// line on stderr and a non-zero exit (2 for usage errors, 1 for failures while running).

#include <csignal>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include "cli/bench_command.hpp"
#include "cli/command_line.hpp"
#include "cli/compare_command.hpp"
#include "cli/fracture_command.hpp"
#include "cli/merge_command.hpp"
#include "cli/play_command.hpp"
#include "cli/render_command.hpp"
#include "cli/run_command.hpp"
#include "cli/suite_command.hpp"
#include "cli/sweep_command.hpp"
#include "experiments/process_runner.hpp"
#include "io/atomic_file.hpp"
#include "io/input_error.hpp"
#include "sim/run.hpp"

using namespace fragsim;
using cli::UsageError;

namespace {

constexpr int kUsageError = 2;

const char* kUsage =
    "usage: fragsim <command> [options]\n"
    "commands:\n"
    "  run      one strategy on a scene (with `none` as the deviation reference)\n"
    "  compare  every strategy on the same scene and seed\n"
    "  sweep    scene keys over values and seeds, every combination compared, one CSV file\n"
    "  suite    every strategy on a fixed battery of scenes, seeds and camera modes: a verdict\n"
    "  merge    join the slices of a sweep or suite run with --shard K/N into one CSV file\n"
    "  render   frames of one strategy's run as PNG files (what the camera sees)\n"
    "  bench    run time against error: step sizes, solvers, predictors, skips vs a reference\n"
    "  fracture the pieces a scene's object breaks into, as a .glb or .obj file\n"
    "  play     fly the camera yourself in a window, switch strategies, replay the flight\n"
    "'fragsim <command> --help' lists a command's options and every scene key.\n";

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << kUsage;
    return kUsageError;
  }
  const std::string command = argv[1];
  remove_temporaries_on_interrupt();
  const std::vector<std::string> args(argv + 2, argv + argc);
  try {
    if (command == "run") return cli::cmd_run(args);
    if (command == "compare") return cli::cmd_compare(args);
    if (command == "sweep") return cli::cmd_sweep(args);
    if (command == "suite") return cli::cmd_suite(args);
    if (command == "merge") return cli::cmd_merge(args);
    if (command == "render") return cli::cmd_render(args);
    if (command == "bench") return cli::cmd_bench(args);
    if (command == "fracture") return cli::cmd_fracture(args);
    if (command == "play") return cli::cmd_play(args);
    if (command == "--help" || command == "-h" || command == "help") {
      std::cout << kUsage;
      return 0;
    }
    std::cerr << "fragsim: unknown command '" << command << "'\n" << kUsage;
    return kUsageError;
  } catch (const Interrupted& e) {
    // Unwound to here, every temporary file is gone, so die of the signal as if never caught.
    std::signal(e.signal(), SIG_DFL);
    std::raise(e.signal());
    return 128 + e.signal();
  } catch (const UsageError& e) {
    std::cerr << "fragsim " << command << ": " << e.what() << '\n';
    return kUsageError;
  } catch (const InputError& e) {
    // Bad input found only once the run has begun (a piece too light for ODE) is still bad input.
    std::cerr << "fragsim " << command << ": " << e.what() << '\n';
    return kUsageError;
  } catch (const std::exception& e) {
    std::cerr << "fragsim " << command << ": " << e.what() << '\n';
    return 1;
  }
}
