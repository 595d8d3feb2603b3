// The fragsim executable (cli/main.cpp): the commands' dispatch, `run` and `compare`; exit codes
// and one-line errors for bad input.

#include <gtest/gtest.h>

#include "support/run_fragsim.hpp"

#include <string>

namespace {

using fragsim::test::Result;
Result fragsim(const std::string& args) {
  return fragsim::test::run_fragsim(args);
}

int lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

const std::string kScene = std::string(FRAGSIM_DATA_DIR) + "/scenes/front.ini";

TEST(Main, UnknownCommandIsAUsageError) {
  const Result r = fragsim("explode");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("unknown command 'explode'"), std::string::npos);
}

TEST(Main, UnknownStrategyIsNamed) {
  const Result r = fragsim("compare --scene " + kScene + " --strategies none,teleport");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(lines(r.out), 1) << r.out;
  EXPECT_NE(r.out.find("teleport"), std::string::npos) << r.out;
}

TEST(Main, RunPrintsATableRow) {
  const Result r = fragsim("run --scene " + kScene + " --strategy none --object.splits 4");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("\nnone "), std::string::npos) << r.out;
}

}  // namespace
