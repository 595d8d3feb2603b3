// Output files appear whole or not at all: the fragsim executable, interrupted and rerun. Signals
// land at a known step (FRAGSIM_TEST_RAISE_AT_STEP, support/signal_at_step.cpp), never after a
// guessed time. That another process writes the same bytes is in
// tests/experiments/determinism_test.cpp.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/run_fragsim.hpp"
#include "support/test_files.hpp"

namespace {

namespace fs = std::filesystem;
using fragsim::test::read_all;
using fragsim::test::run_fragsim_status;
using fragsim::test::shell;
using fragsim::test::UniqueDir;

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
    EXPECT_FALSE(fs::exists(out));  // created for the run, removed with it
    expect_empty(tmp.path());
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
  EXPECT_FALSE(fs::exists(out));
  expect_empty(tmp.path());
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

// `args` run with a file-size limit of `limit_kib` (a full disk, for root too) and SIGXFSZ ignored
// (so a write past it fails instead of killing): the exit code; stderr goes to `err`.
int run_on_a_full_disk(const std::string& args, int limit_kib, const fs::path& err) {
  return shell("bash -c 'trap \"\" XFSZ; ulimit -f " + std::to_string(limit_kib) + "; " + kBin +
               args + "' >/dev/null 2>" + err.string());
}

const std::string kShortRun =
    " compare --scene " + kScenes +
    "thesis125.ini --simulation.duration_s 0.2 --strategies none,edge-min";

TEST(OutputSafety, ReportThatCannotBeWrittenLeavesNoFolder) {
  // 8 KiB: the contact sheet (tens of KB) is the first file that cannot be written.
  const UniqueDir tmp("fragsim_full_report");
  const fs::path report = tmp.path() / "reports" / "front";
  EXPECT_EQ(run_on_a_full_disk(kShortRun + " --report " + report.string(), 8, tmp.path() / "err"),
            1);
  const std::string err = read_all(tmp.path() / "err");
  EXPECT_NE(err.find(": write failed (disk full?)"), std::string::npos) << err;
  EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
  EXPECT_FALSE(fs::exists(tmp.path() / "reports"));  // both levels were made for it
}

TEST(OutputSafety, CsvFilesAppearAllOrNone) {
  // 16 KiB: the five small files fit, trajectories.csv (125 pieces over 12 steps) does not.
  const UniqueDir tmp("fragsim_full_csv");
  const fs::path out = tmp.path() / "csv";
  EXPECT_EQ(run_on_a_full_disk(kShortRun + " --trajectories --csv " + out.string(), 16,
                               tmp.path() / "err"),
            1);
  const std::string err = read_all(tmp.path() / "err");
  EXPECT_NE(err.find("trajectories.csv: write failed (disk full?)"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(out)) << "summary.csv left: " << fs::exists(out / "summary.csv");
  // The same run with room writes them all.
  EXPECT_EQ(shell(kBin + kShortRun + " --trajectories --csv " + out.string() + " >/dev/null"), 0);
  EXPECT_TRUE(fs::exists(out / "summary.csv"));
  EXPECT_TRUE(fs::exists(out / "trajectories.csv"));
}

TEST(OutputSafety, BakeIntoAFolderIsRefusedBeforeAnyBakeIsWritten) {
  // A folder where the second strategy's bake goes: the first bake must not appear alone.
  const UniqueDir tmp("fragsim_bake_folder");
  fs::create_directories(tmp.path() / "b.edge-min.glb");
  const fs::path err = tmp.path() / "err";
  EXPECT_EQ(shell(kBin + kShortRun + " --force --bake " + (tmp.path() / "b.glb").string() +
                  " >/dev/null 2>" + err.string()),
            2);
  EXPECT_EQ(read_all(err), "fragsim compare: --bake " + (tmp.path() / "b.edge-min.glb").string() +
                               ": is a folder\n");
  EXPECT_FALSE(fs::exists(tmp.path() / "b.none.glb"));
}

TEST(OutputSafety, RenderThatFailsPartWayLeavesNoFrame) {
  const UniqueDir tmp("fragsim_full_render");
  const std::string render = " render --scene " + kScenes +
                             "thesis125.ini --simulation.duration_s 0.2 --strategy none "
                             "--steps 0:3 --out ";
  // With room: the frames grow as the pieces spread, so a limit just above the first frame's size
  // lets it be written and stops a later one.
  ASSERT_EQ(shell(kBin + render + (tmp.path() / "room").string() + " >/dev/null"), 0);
  const std::uintmax_t first = fs::file_size(tmp.path() / "room" / "frame_00000.png");
  std::uintmax_t largest = 0;
  for (const auto& e : fs::directory_iterator(tmp.path() / "room")) {
    largest = std::max(largest, fs::file_size(e.path()));
  }
  const int limit_kib = static_cast<int>((first + 1023) / 1024);
  ASSERT_GT(largest, static_cast<std::uintmax_t>(limit_kib) * 1024) << "frames too alike";
  const fs::path out = tmp.path() / "frames";
  EXPECT_EQ(run_on_a_full_disk(render + out.string(), limit_kib, tmp.path() / "err"), 1);
  const std::string err = read_all(tmp.path() / "err");
  EXPECT_NE(err.find(": write failed (disk full?)"), std::string::npos) << err;
  EXPECT_FALSE(fs::exists(out / "frame_00000.png"));
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
