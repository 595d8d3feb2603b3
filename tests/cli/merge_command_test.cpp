// `fragsim merge` end to end (cli/merge_command.cpp), with the slices `fragsim sweep --shard` and
// `fragsim suite --shard` write: merged, they are the unsharded file byte for byte, for several N
// including N above the number of jobs; every refusal is one line. The slices' parts on hand-made
// slices are in tests/experiments/shard_test.cpp.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "experiments/suite.hpp"
#include "support/run_fragsim.hpp"

namespace fragsim {
namespace {

int lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

using test::Result;
using test::run_fragsim;

// 3 distances x 2 seeds = 6 jobs of thesis125 cut to 8 fragments and 0.3 s, none and edge.
const std::string kSweep = "sweep --scene " + std::string(FRAGSIM_DATA_DIR) +
                           "/scenes/thesis125.ini --object.splits 2 --simulation.duration_s 0.3 "
                           "--vary object.distance_m=3,5,7 --seeds 2 --strategies none,edge "
                           "--jobs 1";

std::vector<std::string> shard_files(const std::string& command, const std::string& dir,
                                     std::size_t n) {
  std::vector<std::string> files;
  for (std::size_t k = 0; k < n; ++k) {
    const std::string f = dir + "/shard_" + std::to_string(k) + "_of_" + std::to_string(n) + ".csv";
    const Result r = run_fragsim(command + " --shard " + std::to_string(k) + "/" +
                                 std::to_string(n) + " --out " + f);
    EXPECT_EQ(r.status, 0) << r.out;
    files.push_back(f);
  }
  return files;
}

std::string merge_args(const std::string& out, const std::vector<std::string>& files) {
  std::string args = "merge " + out;
  for (const std::string& f : files) args += " " + f;
  return args;
}

TEST(MergeCommand, MergedSweepSlicesAreTheUnshardedFileByteForByte) {
  const test::UniqueDir dir("fragsim_shard_sweep");
  const Result whole = run_fragsim(kSweep + " --out " + dir.str() + "/whole.csv");
  ASSERT_EQ(whole.status, 0) << whole.out;
  const std::string expected = read_file(dir.str() + "/whole.csv");
  ASSERT_EQ(lines(expected), 1 + 6 * 2);
  for (std::size_t n : {1u, 2u, 4u, 6u, 9u}) {  // 9 > 6 jobs: three empty slices
    SCOPED_TRACE("N = " + std::to_string(n));
    const std::vector<std::string> files = shard_files(kSweep, dir.str(), n);
    const std::string out = dir.str() + "/merged_" + std::to_string(n) + ".csv";
    const Result m = run_fragsim(merge_args(out, files));
    ASSERT_EQ(m.status, 0) << m.out;
    EXPECT_EQ(read_file(out), expected);
    EXPECT_NE(m.out.find("12 rows from " + std::to_string(n) + " slices"), std::string::npos)
        << m.out;
    // The per-value tables of a one-key sweep, as the unsharded command printed them.
    const std::string tables = whole.out.substr(whole.out.find("\nnone: seeds"));
    EXPECT_NE(m.out.find(tables), std::string::npos) << m.out << "\n---\n" << whole.out;
  }
  // A slice is its jobs' rows of the whole file after the slice line: 6 jobs in 4 are 1,2,1,2.
  const std::string s1 = read_file(dir.str() + "/shard_1_of_4.csv");
  EXPECT_EQ(s1.rfind("# fragsim slice: command=sweep shard=1/4 plan=", 0), 0u) << s1;
  EXPECT_NE(s1.find(" jobs=1-3/6 rows=4\n"), std::string::npos) << s1;
  EXPECT_EQ(lines(s1), 2 + 4);
}

TEST(MergeCommand, MergeRefusesOtherPlansRepeatsAndGapsAndWritesNothing) {
  const test::UniqueDir dir("fragsim_shard_refuse");
  const std::vector<std::string> files = shard_files(kSweep, dir.str(), 3);
  // The same sweep with other seeds is another plan.
  const std::string other = dir.str() + "/other.csv";
  std::string other_plan = kSweep;
  other_plan.replace(other_plan.find("--seeds 2"), 9, "--seed-list 5,6");
  ASSERT_EQ(run_fragsim(other_plan + " --shard 1/3 --out " + other).status, 0);
  const std::string out = dir.str() + "/merged.csv";
  struct Case {
    std::vector<std::string> slices;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {{files[0], other, files[2]}, other + ": a slice of another plan"},
      {{files[0], files[1], files[1], files[2]}, "slice 1/3 is given twice"},
      {{files[0], files[2]}, "missing slice 1/3 (2 of 3 given)"},
      {{files[0], files[1], files[2], dir.str() + "/absent.csv"}, "absent.csv"},
  };
  for (const Case& c : cases) {
    const Result r = run_fragsim(merge_args(out, c.slices));
    EXPECT_EQ(r.status, 2) << r.out;
    EXPECT_EQ(lines(r.out), 1) << r.out;
    EXPECT_NE(r.out.find(c.expected), std::string::npos) << r.out;
    EXPECT_FALSE(std::filesystem::exists(out));
  }
  const Result plain = run_fragsim(merge_args(out, {files[0], dir.str() + "/../nothing"}));
  EXPECT_EQ(plain.status, 2) << plain.out;
  // OUT exists: only with --force; OUT given as a slice: refused.
  ASSERT_EQ(run_fragsim(merge_args(out, files)).status, 0);
  const Result again = run_fragsim(merge_args(out, files));
  EXPECT_EQ(again.status, 2);
  EXPECT_NE(again.out.find("--force"), std::string::npos) << again.out;
  EXPECT_EQ(
      run_fragsim("merge --force " + out + " " + files[0] + " " + files[1] + " " + files[2]).status,
      0);
  const Result self = run_fragsim(merge_args(files[0], files));
  EXPECT_EQ(self.status, 2);
  EXPECT_NE(self.out.find("is also given as a slice"), std::string::npos) << self.out;
  EXPECT_EQ(run_fragsim("merge " + out).status, 2);
}

TEST(MergeCommand, BadShardIsOneLineNamingTheOption) {
  const test::UniqueDir dir("fragsim_shard_bad");
  for (const char* bad : {"4/4", "x", "1/0", "-1/2"}) {
    const Result r =
        run_fragsim(kSweep + " --shard " + std::string(bad) + " --out " + dir.str() + "/x.csv");
    EXPECT_EQ(r.status, 2) << bad << ": " << r.out;
    EXPECT_EQ(lines(r.out), 1) << r.out;
    EXPECT_EQ(r.out.rfind("fragsim sweep: --shard ", 0), 0u) << r.out;
    const Result s =
        run_fragsim("suite --shard " + std::string(bad) + " --out " + dir.str() + "/y.csv");
    EXPECT_EQ(s.status, 2) << bad << ": " << s.out;
    EXPECT_EQ(lines(s.out), 1) << s.out;
    EXPECT_EQ(s.out.rfind("fragsim suite: --shard ", 0), 0u) << s.out;
  }
  const Result no_out = run_fragsim("suite --shard 0/2");
  EXPECT_EQ(no_out.status, 2);
  EXPECT_NE(no_out.out.find("--shard: needs --out"), std::string::npos) << no_out.out;
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

TEST(MergeCommand, AFailingJobIsNamedByItsNumberInTheWholePlan) {
  // 5 jobs of 60 steps; slice 1/2 holds jobs 3, 4 and 5. On 2 workers, worker 0 runs jobs 3 and
  // 5, so its step 100 (support/signal_at_step.cpp) falls in job 5, where it kills itself.
  const test::UniqueDir dir("fragsim_shard_crash");
  for (const auto& [name, value] :
       {std::pair<const char*, const char*>{"FRAGSIM_TEST_RAISE_AT_STEP", "100"},
        {"FRAGSIM_TEST_RAISE_SIGNAL", "KILL"},
        {"FRAGSIM_TEST_RAISE_IN", "self"}}) {
    ::setenv(name, value, 1);
  }
  const Result r = run_fragsim("sweep --scene " + std::string(FRAGSIM_DATA_DIR) +
                               "/scenes/thesis125.ini --object.splits 2 --simulation.duration_s "
                               "0.5 --vary object.distance_m=3,5,7,9,11 --strategies none,edge "
                               "--jobs 2 --shard 1/2 --out " +
                               dir.str() + "/x.csv");
  for (const char* name :
       {"FRAGSIM_TEST_RAISE_AT_STEP", "FRAGSIM_TEST_RAISE_SIGNAL", "FRAGSIM_TEST_RAISE_IN"}) {
    ::unsetenv(name);
  }
  EXPECT_EQ(r.status, 1) << r.out;
  EXPECT_EQ(r.out,
            "fragsim sweep: job 5 (object.distance_m=11, seed 1): the worker process was killed "
            "by signal 9 (Killed)\n");
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

// The suite's CSV without strategy_ms_median, its one timing column (suite_command_test.cpp).
std::string without_timing(const std::string& csv) {
  std::istringstream in(csv);
  std::string out, line;
  while (std::getline(in, line)) out += line.substr(0, line.rfind(',')) + "\n";
  return out;
}

// Printed tables without each line's last word (strat_ms in a table row).
std::string without_timing_words(const std::string& text) {
  std::istringstream in(text);
  std::string out, line;
  while (std::getline(in, line)) {
    if (line.rfind("wrote ", 0) == 0) continue;
    out += line.substr(0, line.rfind(' ')) + "\n";
  }
  return out;
}

TEST(MergeCommand, MergedSuiteSlicesAreTheUnshardedFileButForTheTimingColumn) {
  const test::UniqueDir dir("fragsim_shard_suite");
  // 3 runs: thesis125 at 4 m, aim future, three speeds, path camera, seed 1.
  const std::string suite = "suite --scene-dir " + std::string(FRAGSIM_DATA_DIR) +
                            "/scenes --scenes thesis125 --modes path --seeds 1 --limit 3 --jobs 1";
  const Result whole = run_fragsim(suite + " --out " + dir.str() + "/whole.csv");
  ASSERT_EQ(whole.status, 0) << whole.out;
  const std::string expected = read_file(dir.str() + "/whole.csv");
  ASSERT_EQ(lines(expected), 1 + 3 * static_cast<int>(suite_variants().size()));
  for (std::size_t n : {2u, 4u}) {  // 4 > 3 runs: one empty slice
    SCOPED_TRACE("N = " + std::to_string(n));
    const std::vector<std::string> files = shard_files(suite, dir.str(), n);
    const std::string out = dir.str() + "/merged_" + std::to_string(n) + ".csv";
    const Result m = run_fragsim(merge_args(out, files));
    ASSERT_EQ(m.status, 0) << m.out;
    const std::string merged = read_file(out);
    EXPECT_EQ(lines(merged), lines(expected));
    EXPECT_EQ(without_timing(merged), without_timing(expected));
    // The tables and the recommendation, as the unsharded command printed them but for the
    // timing column (each table line's last number).
    const auto tables = [](const std::string& out) {
      return without_timing_words(out.substr(out.find("suite: ")));
    };
    EXPECT_EQ(tables(m.out), tables(whole.out)) << m.out;
    EXPECT_NE(m.out.find("most robust"), std::string::npos) << m.out;
  }
  // A suite slice does not merge with a sweep slice.
  std::filesystem::create_directory(dir.path() / "sweep");
  const std::vector<std::string> sweep = shard_files(kSweep, dir.str() + "/sweep", 2);
  const Result mixed = run_fragsim(
      merge_args(dir.str() + "/mixed.csv", {dir.str() + "/shard_0_of_4.csv", sweep[1]}));
  EXPECT_EQ(mixed.status, 2) << mixed.out;
  EXPECT_NE(mixed.out.find("a sweep slice;"), std::string::npos) << mixed.out;
}

}  // namespace
}  // namespace fragsim
