// Output files appear whole or not at all: the fragsim executable, interrupted and rerun. Signals
// land at a known step (FRAGSIM_TEST_RAISE_AT_STEP, sim/simulation.hpp), never after a guessed
// time. That another process writes the same bytes is in tests/experiments/determinism_test.cpp.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/run_fragsim.hpp"

namespace {

namespace fs = std::filesystem;
using fragsim::test::run_fragsim_status;
using fragsim::test::UniqueDir;

int shell(const std::string& cmd) {
  const int raw = std::system(cmd.c_str());
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

std::string read_all(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

const std::string kBin = FRAGSIM_BINARY;
const std::string kScenes = std::string(FRAGSIM_DATA_DIR) + "/scenes/";

// The signal `name` sent to fragsim once its processes have simulated `step` steps in all.
std::vector<std::pair<std::string, std::string>> signal_at(int step, const std::string& name) {
  return {{"FRAGSIM_TEST_RAISE_AT_STEP", std::to_string(step)},
          {"FRAGSIM_TEST_RAISE_SIGNAL", name}};
}

bool died_of(int status, int signo) {
  return WIFSIGNALED(status) && WTERMSIG(status) == signo;
}

void expect_empty(const fs::path& dir) {
  for (const auto& entry : fs::directory_iterator(dir)) {
    ADD_FAILURE() << "left behind: " << entry.path().filename();
  }
}

// The default scene, 180 steps of 1728 fragments, with trajectories: --trajectories runs every
// strategy in this one process, so step 90 of the `none` run lands while trajectories.csv is
// being written.
const std::string kRun = " compare --scene " + kScenes + "front.ini --trajectories --force";

TEST(OutputSafety, InterruptedRunLeavesNoFileAndNoDebris) {
  for (const char* name : {"TERM", "INT"}) {
    const UniqueDir tmp("fragsim_interrupted");
    const fs::path out = tmp.path() / "csv";
    const int status = run_fragsim_status(kRun + " --csv " + out.string(), signal_at(90, name));
    EXPECT_TRUE(died_of(status, std::string(name) == "TERM" ? SIGTERM : SIGINT))
        << name << ": wait status " << status;
    ASSERT_TRUE(fs::exists(out));  // created before the run
    expect_empty(out);
  }
}

TEST(OutputSafety, InterruptedWorkersLeaveNoFileAndNoDebris) {
  // Without --trajectories the strategies after `none` run in 2 workers; `none` takes the first
  // 180 steps in the parent, so step 210 is counted in a worker, which signals the parent.
  const UniqueDir tmp("fragsim_interrupted_workers");
  const fs::path out = tmp.path() / "csv";
  const int status =
      run_fragsim_status(" compare --scene " + kScenes + "front.ini --jobs 2 --csv " + out.string(),
                         signal_at(210, "TERM"));
  EXPECT_TRUE(died_of(status, SIGTERM)) << "wait status " << status;
  ASSERT_TRUE(fs::exists(out));
  expect_empty(out);
}

TEST(OutputSafety, InterruptedSweepLeavesNoFileAndNoDebris) {
  // Every job runs in a worker (30 steps of none, then 30 of edge): step 40 is inside one.
  for (const char* name : {"TERM", "INT"}) {
    const UniqueDir tmp("fragsim_interrupted_sweep");
    const int status = run_fragsim_status(
        "sweep --scene " + kScenes +
            "thesis125.ini --object.splits 2 --simulation.duration_s 0.5 --vary "
            "object.distance_m=3,5 --seeds 2 --strategies none,edge --jobs 2 --out " +
            (tmp.path() / "sweep.csv").string(),
        signal_at(40, name));
    EXPECT_TRUE(died_of(status, std::string(name) == "TERM" ? SIGTERM : SIGINT))
        << name << ": wait status " << status;
    expect_empty(tmp.path());
  }
}

TEST(OutputSafety, KilledRunKeepsTheOldFilesWhole) {
  const UniqueDir tmp("fragsim_killed");
  const fs::path out = tmp.path() / "csv";
  ASSERT_EQ(shell(kBin + " compare --scene " + kScenes + "thesis125.ini --csv " + out.string() +
                  " >/dev/null"),
            0);
  const std::string old_summary = read_all(out / "summary.csv");
  ASSERT_FALSE(old_summary.empty());
  // SIGKILL cannot be caught: the temporary file stays, the old summary must stay whole.
  const int status = run_fragsim_status(kRun + " --csv " + out.string(), signal_at(90, "KILL"));
  EXPECT_TRUE(died_of(status, SIGKILL)) << "wait status " << status;
  EXPECT_EQ(read_all(out / "summary.csv"), old_summary);
  EXPECT_FALSE(fs::exists(out / "trajectories.csv"));
}

TEST(OutputSafety, KilledSweepWritesNoFile) {
  const UniqueDir tmp("fragsim_killed_sweep");
  const int status = run_fragsim_status(
      "sweep --scene " + kScenes +
          "thesis125.ini --object.splits 2 --simulation.duration_s 0.5 --vary "
          "object.distance_m=3,5 --seeds 2 --strategies none,edge --jobs 2 --out " +
          (tmp.path() / "sweep.csv").string(),
      signal_at(40, "KILL"));
  EXPECT_TRUE(died_of(status, SIGKILL)) << "wait status " << status;
  EXPECT_FALSE(fs::exists(tmp.path() / "sweep.csv"));
}

TEST(OutputSafety, ExistingFolderIsNotOverwrittenWithoutForce) {
  const UniqueDir tmp("fragsim_noforce");
  const std::string run = kBin + " run --strategy none --scene " + kScenes +
                          "thesis125.ini --simulation.duration_s 0.2 --csv " +
                          (tmp.path() / "csv").string();
  ASSERT_EQ(shell(run + " >/dev/null"), 0);
  EXPECT_EQ(shell(run + " >/dev/null 2>&1"), 2);
  EXPECT_EQ(shell(run + " --force >/dev/null"), 0);
}

TEST(OutputSafety, UnwritableFolderIsAOneLineError) {
  const UniqueDir tmp("fragsim_unwritable");
  const std::string out_file = (tmp.path() / "out.txt").string();
  const int status = shell(kBin + " run --scene " + kScenes +
                           "thesis125.ini --csv /proc/fragsim/cannot >" + out_file + " 2>&1");
  EXPECT_EQ(status, 2);
  const std::string out = read_all(out_file);
  EXPECT_NE(out.find("--csv: /proc/fragsim/cannot"), std::string::npos) << out;
}

}  // namespace
