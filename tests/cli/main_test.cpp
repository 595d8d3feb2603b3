// The fragsim executable's dispatch (cli/main.cpp): a command it does not know is a usage error
// with exit code 2.

#include <gtest/gtest.h>

#include <string>

#include "support/run_fragsim.hpp"

namespace {

using fragsim::test::Result;
using fragsim::test::run_fragsim;

TEST(Main, UnknownCommandIsAUsageError) {
  const Result r = run_fragsim("explode");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("unknown command 'explode'"), std::string::npos);
}

TEST(Main, NoCommandPrintsTheUsage) {
  const Result r = run_fragsim("");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("usage: fragsim <command> [options]"), std::string::npos) << r.out;
}

}  // namespace
