// `fragsim compare` (cli/compare_command.cpp): bad strategy lists and output options are one line
// naming the option, exit code 2, before anything runs.

#include <gtest/gtest.h>

#include <string>

#include "support/run_fragsim.hpp"

namespace {

using fragsim::test::Result;
using fragsim::test::run_fragsim;

int lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

const std::string kScene = std::string(FRAGSIM_DATA_DIR) + "/scenes/front.ini";

TEST(CompareCommand, UnknownStrategyIsNamed) {
  const Result r = run_fragsim("compare --scene " + kScene + " --strategies none,teleport");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(lines(r.out), 1) << r.out;
  EXPECT_NE(r.out.find("teleport"), std::string::npos) << r.out;
}

TEST(CompareCommand, OutputOptionsWithoutWhatTheyNeedAreRefused) {
  const Result trajectories = run_fragsim("compare --scene " + kScene + " --trajectories");
  EXPECT_EQ(trajectories.status, 2);
  EXPECT_EQ(trajectories.out, "fragsim compare: --trajectories: needs --csv DIR\n");
  const Result empty_csv = run_fragsim("compare --scene " + kScene + " --csv ''");
  EXPECT_EQ(empty_csv.status, 2);
  EXPECT_EQ(empty_csv.out, "fragsim compare: --csv: empty folder name\n");
  const Result bake_limit = run_fragsim("compare --scene " + kScene + " --bake-max-mb 5");
  EXPECT_EQ(bake_limit.status, 2);
  EXPECT_EQ(bake_limit.out, "fragsim compare: --bake-max-mb: needs --bake FILE.glb\n");
}

}  // namespace
