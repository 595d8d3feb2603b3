// Output files appear whole or not at all, and the same scene and seed give the same bytes in
// another process: the fragsim executable, interrupted and rerun.

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace {

namespace fs = std::filesystem;

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

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::path(::testing::TempDir()) / name;
  fs::remove_all(d);
  return d;
}

// 20 s of the default scene with trajectories: many seconds of work, so the signal lands midway.
const std::string kLongRun =
    " compare --scene " + kScenes + "front.ini --simulation.duration_s 20 --trajectories --force";

TEST(OutputSafety, InterruptedRunLeavesNoFileAndNoDebris) {
  const fs::path dir = fresh_dir("fragsim_interrupted");
  const int status =
      shell("timeout -s TERM 1 " + kBin + kLongRun + " --csv " + dir.string() + " >/dev/null 2>&1");
  ASSERT_EQ(status, 124) << "the run was not interrupted (timeout's status for a killed command)";
  ASSERT_TRUE(fs::exists(dir));  // created before the run
  for (const auto& entry : fs::directory_iterator(dir)) {
    ADD_FAILURE() << "left behind: " << entry.path().filename();
  }
}

TEST(OutputSafety, KilledRunKeepsTheOldFilesWhole) {
  const fs::path dir = fresh_dir("fragsim_killed");
  ASSERT_EQ(shell(kBin + " compare --scene " + kScenes + "thesis125.ini --csv " + dir.string() +
                  " >/dev/null"),
            0);
  const std::string old_summary = read_all(dir / "summary.csv");
  ASSERT_FALSE(old_summary.empty());
  // SIGKILL cannot be caught: the temporary file stays, the old summary must stay whole.
  const int status =
      shell("timeout -s KILL 1 " + kBin + kLongRun + " --csv " + dir.string() + " >/dev/null 2>&1");
  ASSERT_EQ(status, 137);
  EXPECT_EQ(read_all(dir / "summary.csv"), old_summary);
  EXPECT_FALSE(fs::exists(dir / "trajectories.csv"));
}

TEST(OutputSafety, ExistingFolderIsNotOverwrittenWithoutForce) {
  const fs::path dir = fresh_dir("fragsim_noforce");
  const std::string run = kBin + " run --strategy none --scene " + kScenes +
                          "thesis125.ini --simulation.duration_s 0.2 --csv " + dir.string();
  ASSERT_EQ(shell(run + " >/dev/null"), 0);
  EXPECT_EQ(shell(run + " >/dev/null 2>&1"), 2);
  EXPECT_EQ(shell(run + " --force >/dev/null"), 0);
}

TEST(OutputSafety, UnwritableFolderIsAOneLineError) {
  const std::string out_file = ::testing::TempDir() + "/fragsim_out.txt";
  const int status = shell(kBin + " run --scene " + kScenes +
                           "thesis125.ini --csv /proc/fragsim/cannot >" + out_file + " 2>&1");
  EXPECT_EQ(status, 2);
  const std::string out = read_all(out_file);
  EXPECT_NE(out.find("--csv: /proc/fragsim/cannot"), std::string::npos) << out;
}

TEST(Determinism, TwoProcessesWriteTheSameBytes) {
  const fs::path a = fresh_dir("fragsim_det_a");
  const fs::path b = fresh_dir("fragsim_det_b");
  for (const fs::path& d : {a, b}) {
    ASSERT_EQ(shell(kBin + " compare --scene " + kScenes + "thesis125.ini --trajectories --csv " +
                    d.string() + " >/dev/null"),
              0);
  }
  for (const char* f :
       {"summary.csv", "steps.csv", "camera.csv", "trajectories.csv", "config.ini"}) {
    const std::string bytes = read_all(a / f);
    EXPECT_FALSE(bytes.empty()) << f;
    EXPECT_EQ(bytes, read_all(b / f)) << f;
  }
}

}  // namespace
