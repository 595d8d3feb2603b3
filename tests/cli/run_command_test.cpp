// `fragsim run` (cli/run_command.cpp): one strategy's row, and --dump-control's refusals, each one
// line with exit code 2.

#include <gtest/gtest.h>

#include <string>

#include "support/run_fragsim.hpp"

namespace {

using fragsim::test::Result;
using fragsim::test::run_fragsim;

const std::string kScene = std::string(FRAGSIM_DATA_DIR) + "/scenes/front.ini";

TEST(RunCommand, PrintsATableRow) {
  const Result r = run_fragsim("run --scene " + kScene + " --strategy none --object.splits 4");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("\nnone "), std::string::npos) << r.out;
}

TEST(RunCommand, DumpControlRunsTheStrategyAloneAndSaysSo) {
  const Result with_csv =
      run_fragsim("run --scene " + kScene + " --strategy edge-min --dump-control x.bin --csv out");
  EXPECT_EQ(with_csv.status, 2);
  EXPECT_EQ(with_csv.out, "fragsim run: --dump-control: runs the strategy alone; not with --csv\n");
  const Result not_in_library =
      run_fragsim("run --scene " + kScene + " --strategy wall --dump-control x.bin");
  EXPECT_EQ(not_in_library.status, 2);
  EXPECT_EQ(not_in_library.out,
            "fragsim run: --dump-control: strategy 'wall' is not in the controller library "
            "(edge-min, edge, deflect-all)\n");
}

}  // namespace
