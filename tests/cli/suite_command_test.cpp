// `fragsim suite` end to end (cli/suite_command.cpp): a slice gives the same CSV for any --jobs;
// bad input is one line and status 2.

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "experiments/suite.hpp"
#include "support/run_fragsim.hpp"

namespace fragsim {
namespace {

const std::string kSceneDir = std::string(FRAGSIM_DATA_DIR) + "/scenes";

// ---- The command, end to end. ----

int lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

std::string read(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The CSV without its last column, strategy_ms_median: the only one that is a timing.
std::string without_timing(const std::string& csv) {
  std::istringstream in(csv);
  std::string out, line;
  while (std::getline(in, line)) out += line.substr(0, line.rfind(',')) + "\n";
  return out;
}

std::string slice_args(const std::string& out, int jobs) {
  // 2 entries x 1 seed: thesis125 at 4 m, aim future, speeds 3 and 6 m/s, path camera.
  return "suite --scene-dir " + kSceneDir +
         " --scenes thesis125 --modes path --seeds 1 --limit 2 --jobs " + std::to_string(jobs) +
         " --force --out " + out;
}

TEST(SuiteCommand, SliceGivesTheSameCsvForAnyJobs) {
  const std::string a = ::testing::TempDir() + "/fragsim_suite_j1.csv";
  const std::string b = ::testing::TempDir() + "/fragsim_suite_j2.csv";
  const test::Result r1 = test::run_fragsim(slice_args(a, 1));
  const test::Result r2 = test::run_fragsim(slice_args(b, 2));
  ASSERT_EQ(r1.status, 0) << r1.out;
  ASSERT_EQ(r2.status, 0) << r2.out;
  const std::string ca = read(a), cb = read(b);
  EXPECT_EQ(lines(ca), 1 + 2 * static_cast<int>(suite_variants().size()));
  EXPECT_EQ(without_timing(ca), without_timing(cb));
  EXPECT_NE(r1.out.find("mode path"), std::string::npos) << r1.out;
  EXPECT_NE(r1.out.find("most robust"), std::string::npos) << r1.out;
  EXPECT_NE(ca.find("thesis125,4,future,3,1,path,edge-min/reachable,"), std::string::npos) << ca;
  EXPECT_NE(ca.find("thesis125,4,future,6,1,path,none,"), std::string::npos) << ca;
}

void expect_usage_error(const std::string& args, const std::string& option) {
  const test::Result r = test::run_fragsim(args);
  EXPECT_EQ(r.status, 2) << args << ": " << r.out;
  EXPECT_EQ(lines(r.out), 1) << args << ": " << r.out;
  EXPECT_NE(r.out.find(option), std::string::npos) << args << ": " << r.out;
}

TEST(SuiteCommand, BadInputIsOneLineNamingTheOption) {
  expect_usage_error("suite --frobnicate", "--frobnicate");
  expect_usage_error("suite front", "'front'");
  expect_usage_error("suite --seeds 0", "--seeds");
  expect_usage_error("suite --seeds many", "--seeds");
  expect_usage_error("suite --scenes nowhere", "--scenes");
  expect_usage_error("suite --modes drone", "--modes");
  expect_usage_error("suite --jobs 0", "--jobs");
  expect_usage_error("suite --limit 0", "--limit");
  expect_usage_error("suite --scene-dir /nonexistent/scenes", "--scene-dir");
  expect_usage_error("suite --scene-dir " + kSceneDir + " --out /nonexistent/dir/suite.csv",
                     "--out");
}

TEST(SuiteCommand, HelpListsTheOptions) {
  const test::Result r = test::run_fragsim("suite --help");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("--seeds"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("1440 runs"), std::string::npos) << r.out;
}

}  // namespace
}  // namespace fragsim
