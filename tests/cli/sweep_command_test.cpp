// `fragsim sweep` end to end (cli/sweep_command.cpp): the same bytes whatever the number of worker
// processes; a bad --vary value, and a worker that dies, are one line naming what went wrong.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "support/run_fragsim.hpp"

namespace fragsim {
namespace {

// ---- The command end to end. ----

using test::Result;
Result fragsim(const std::string& args) {
  return test::run_fragsim(args);
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

int lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

const std::string kTiny = "sweep --scene " + std::string(FRAGSIM_DATA_DIR) +
                          "/scenes/thesis125.ini --object.splits 2 --simulation.duration_s 0.5 "
                          "--vary object.distance_m=3,5 --seeds 2 --strategies none,edge";

std::string fresh_dir(const std::string& name) {
  const std::string dir = ::testing::TempDir() + "/" + name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

TEST(SweepCommand, OutputIsTheSameWhateverTheNumberOfWorkers) {
  const std::string dir = fresh_dir("fragsim_sweep_e2e");
  const Result one = fragsim(kTiny + " --jobs 1 --out " + dir + "/one.csv");
  ASSERT_EQ(one.status, 0) << one.out;
  const Result two = fragsim(kTiny + " --jobs 2 --out " + dir + "/two.csv");
  ASSERT_EQ(two.status, 0) << two.out;
  const std::string a = read_file(dir + "/one.csv");
  const std::string b = read_file(dir + "/two.csv");
  EXPECT_EQ(a, b);
  EXPECT_EQ(lines(a), 1 + 2 * 2 * 2);  // header + 2 values x 2 seeds x 2 strategies
  EXPECT_EQ(a.rfind("object.distance_m,seed,scene,strategy,", 0), 0u) << a;
  EXPECT_NE(a.find("\n5,2,thesis125,edge,"), std::string::npos) << a;
  EXPECT_NE(one.out.find("smallest object.distance_m"), std::string::npos) << one.out;
  // Only the two outputs: every worker's temporary file is gone.
  int files = 0;
  for (const auto& f : std::filesystem::directory_iterator(dir)) files += f.is_regular_file();
  EXPECT_EQ(files, 2);

  const Result again = fragsim(kTiny + " --jobs 2 --out " + dir + "/one.csv");
  EXPECT_EQ(again.status, 2) << again.out;
  EXPECT_NE(again.out.find("--force"), std::string::npos) << again.out;
  const Result forced = fragsim(kTiny + " --jobs 2 --force --out " + dir + "/one.csv");
  EXPECT_EQ(forced.status, 0) << forced.out;
  EXPECT_EQ(read_file(dir + "/one.csv"), b);
}

TEST(SweepCommand, BadVaryValueIsOneLineNamingOptionAndValue) {
  const std::string dir = fresh_dir("fragsim_sweep_bad");
  const Result r = fragsim(kTiny + " --vary edge.k=1,-2 --out " + dir + "/x.csv");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(lines(r.out), 1) << r.out;
  EXPECT_NE(r.out.find("--vary edge.k=-2"), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(dir + "/x.csv"));

  const Result range = fragsim(kTiny.substr(0, kTiny.find("--vary")) +
                               "--vary object.distance_m=1:5:0 --out " + dir + "/x.csv");
  EXPECT_EQ(range.status, 2);
  EXPECT_EQ(lines(range.out), 1) << range.out;
  EXPECT_NE(range.out.find("step must be > 0"), std::string::npos) << range.out;
}

// Test-only environment variables for one call (sim/simulation.hpp), removed again after it.
class ScopedEnv {
 public:
  explicit ScopedEnv(std::vector<std::pair<std::string, std::string>> vars)
      : vars_(std::move(vars)) {
    for (const auto& [name, value] : vars_) ::setenv(name.c_str(), value.c_str(), 1);
  }
  ~ScopedEnv() {
    for (const auto& [name, value] : vars_) ::unsetenv(name.c_str());
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  std::vector<std::pair<std::string, std::string>> vars_;
};

TEST(SweepCommand, AWorkerThatDiesIsOneLineNamingTheJob) {
  // 3 jobs of 60 steps (none, then edge) on 2 workers: worker 0 runs jobs 1 and 3, worker 1 job 2
  // only, so step 100 of a worker is reached once, in job 3, where that worker kills itself.
  const std::string dir = fresh_dir("fragsim_sweep_crash");
  Result r;
  {
    const ScopedEnv env({{"FRAGSIM_TEST_RAISE_AT_STEP", "100"},
                         {"FRAGSIM_TEST_RAISE_SIGNAL", "KILL"},
                         {"FRAGSIM_TEST_RAISE_IN", "self"}});
    r = fragsim("sweep --scene " + std::string(FRAGSIM_DATA_DIR) +
                "/scenes/thesis125.ini --object.splits 2 --simulation.duration_s 0.5 --vary "
                "object.distance_m=3,5,7 --strategies none,edge --jobs 2 --out " +
                dir + "/x.csv");
  }
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_EQ(r.out,
            "fragsim sweep: job 3 (object.distance_m=7, seed 1): the worker process was killed "
            "by signal 9 (Killed)\n");
  EXPECT_TRUE(std::filesystem::is_empty(dir));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace fragsim
