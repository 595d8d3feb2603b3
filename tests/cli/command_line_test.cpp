// `fragsim` commands' shared parsing (cli/command_line.cpp) through the executable: a bad option
// value, a malformed scene file or a bad --jobs is one line naming what is wrong, exit status 2.

#include <gtest/gtest.h>

#include "support/run_fragsim.hpp"

#include <array>
#include <cstdio>
#include <fstream>
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

TEST(CommandLine, BadOptionValueIsOneLineNamingTheOption) {
  const Result r = fragsim("run --scene " + kScene + " --camera.fovy_deg 190");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(lines(r.out), 1) << r.out;
  EXPECT_NE(r.out.find("--camera.fovy_deg"), std::string::npos) << r.out;
}

TEST(CommandLine, MalformedSceneFileNamesFileAndLine) {
  const std::string path = ::testing::TempDir() + "/fragsim_bad_scene.ini";
  std::ofstream(path) << "[camera]\nnear_m = 0.1\nfar_m = banana\n";
  const Result r = fragsim("run --scene " + path);
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(lines(r.out), 1) << r.out;
  EXPECT_NE(r.out.find(path + ":3: camera.far_m = 'banana'"), std::string::npos) << r.out;
}

TEST(CommandLine, BadJobsIsOneLineNamingJobs) {
  const std::string sweep = "sweep --scene " + kScene + " --vary object.distance_m=3,5 --out " +
                            ::testing::TempDir() + "/fragsim_never_written.csv";
  for (const std::string& command : {"compare --scene " + kScene, sweep}) {
    for (const std::string value : {"0", "-1", "abc"}) {
      const Result r = fragsim(command + " --jobs " + value);
      EXPECT_EQ(r.status, 2) << command << " --jobs " << value << ": " << r.out;
      EXPECT_EQ(lines(r.out), 1) << r.out;
      EXPECT_NE(r.out.find(": --jobs " + value + ": must be a whole number in [1, 1024]\n"),
                std::string::npos)
          << r.out;
    }
  }
}

}  // namespace
