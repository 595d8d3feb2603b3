// `fragsim play` through the executable (cli/play_command.cpp), without a window: bad options,
// and the benchmark mode that flies the scripted route headless.

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "support/run_fragsim.hpp"

namespace fragsim {
namespace {

// Bad options are one line naming the option, exit status 2, before any window opens.
TEST(PlayCommand, BadOptionsAreOneLineAndStatus2) {
  const std::string scene = "--scene " + std::string(FRAGSIM_DATA_DIR) + "/scenes/front.ini ";
  for (const auto& [args, named] : std::vector<std::pair<std::string, std::string>>{
           {"--bench-frames 0", "--bench-frames"},
           {"--bench-frames x", "--bench-frames"},
           {"--record flight.ini", "--record"},
           {"--record /nonexistent-folder/f.csv", "--record"},
           {"--size 10x10", "--size"},
           {"--overlays stars", "--overlays"},
           {"--strategy nosuch", "--strategy"}}) {
    const test::Result r = test::run_fragsim("play " + scene + args);
    EXPECT_EQ(r.status, 2) << args << ": " << r.out;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << args << ": " << r.out;
    EXPECT_NE(r.out.find(named), std::string::npos) << args << ": " << r.out;
  }
}

// The benchmark mode flies the scripted route headless and reports every part of a frame.
TEST(PlayCommand, BenchFramesRunsHeadlessAndRecordsNothing) {
  test::UniqueDir dir("fragsim_play_bench");
  const test::Result r = test::run_fragsim("play --scene " + std::string(FRAGSIM_DATA_DIR) +
                                           "/scenes/thesis125.ini --bench-frames 30 "
                                           "--strategy edge --size 64x36 --record " +
                                           dir.str() + "/f.csv");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("flight 1: edge, 0.500 s (30 steps)"), std::string::npos) << r.out;
  // 31 frames: the explosion's and one per step.
  EXPECT_NE(r.out.find("frames: 31, median / p95 ms: frame "), std::string::npos) << r.out;
  for (const char* part : {"physics", "strategy", "draw", "present"}) {
    EXPECT_NE(r.out.find(std::string("; ") + part + " "), std::string::npos) << part;
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

}  // namespace
}  // namespace fragsim
