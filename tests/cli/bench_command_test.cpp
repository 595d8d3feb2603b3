// `fragsim bench` end to end (cli/bench_command.cpp): the CSV with the reference run first, and
// every bad option a one-line usage error. The bench itself is in
// tests/experiments/time_vs_error_test.cpp.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "support/run_fragsim.hpp"

namespace fragsim {
namespace {

const std::string kSmallScene = std::string(FRAGSIM_DATA_DIR) + "/scenes/thesis125.ini";

TEST(BenchCommand, WritesTheCsvWithTheReferenceFirst) {
  const std::string path = testing::TempDir() + "fragsim_bench_test.csv";
  std::filesystem::remove(path);
  const test::Result r =
      test::run_fragsim("bench --scene " + kSmallScene +
                        " --simulation.duration_s 1 --groups dt --repeats 1 --out " + path);
  ASSERT_EQ(r.status, 0) << r.out;
  std::ifstream in(path);
  std::string header, first;
  std::getline(in, header);
  std::getline(in, first);
  EXPECT_EQ(header.rfind("config,group,overrides,dt_s,steps,compute_s_per_sim_s", 0), 0u) << header;
  EXPECT_EQ(first.rfind("reference,reference,", 0), 0u) << first;
  int rows = 1;
  for (std::string line; std::getline(in, line);) ++rows;
  EXPECT_EQ(rows, 5);  // reference, default (= dt 1/60), dt 1/30, 1/120, 1/240
  EXPECT_NE(r.out.find("dt 1/60: the same simulation as default"), std::string::npos) << r.out;
  std::filesystem::remove(path);
}

TEST(BenchCommand, BadOptionsAreOneLineUsageErrors) {
  struct Case {
    std::string args, needle;
  };
  const std::vector<Case> cases = {
      {"--repeats 0", "--repeats 0: must be in [1, 100]"},
      {"--groups dt,warp", "--groups: no group 'warp'"},
      {"--config nocolon", "--config nocolon: expected NAME:key=value"},
      {"--config x:simulation.dt_s", "is not key=value"},
      {"--strategy bogus", "--strategy:"},
      {"--out /nonexistent-dir/x.csv", "--out:"},
  };
  for (const Case& c : cases) {
    const test::Result r = test::run_fragsim("bench --scene " + kSmallScene + " " + c.args);
    EXPECT_EQ(r.status, 2) << c.args << ": " << r.out;
    EXPECT_NE(r.out.find(c.needle), std::string::npos) << c.args << ": " << r.out;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << c.args << ": " << r.out;
  }
}

}  // namespace
}  // namespace fragsim
