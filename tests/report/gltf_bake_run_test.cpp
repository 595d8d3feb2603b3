// The bake through the command line (`run --bake`, `compare --bake`): the same scene and seed give
// the same bytes in another process, the bake leaves summary.csv as it was, and a path that cannot
// be written or a bake over the size limit is one line naming the option, a non-zero exit and no
// file.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/run_fragsim.hpp"

namespace {

namespace fs = std::filesystem;
using fragsim::test::run_fragsim;
using fragsim::test::UniqueDir;

const std::string kScene = std::string(FRAGSIM_DATA_DIR) + "/scenes/thesis125.ini";

std::string read_all(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

int lines(const std::string& text) {
  int n = 0;
  for (char c : text) n += c == '\n';
  return n;
}

TEST(GltfBakeRun, SameSceneAndSeedGiveTheSameBytes) {
  UniqueDir dir("fragsim_bake");
  const std::string a = (dir.path() / "a.glb").string();
  const std::string b = (dir.path() / "b.glb").string();
  const std::string args = "run --scene " + kScene + " --strategy edge-min --no-occlusion --bake ";
  ASSERT_EQ(run_fragsim(args + a).status, 0);
  ASSERT_EQ(run_fragsim(args + b).status, 0);
  const std::string bytes = read_all(a);
  ASSERT_GT(bytes.size(), 1000u);
  EXPECT_EQ(bytes.substr(0, 4), "glTF");
  EXPECT_TRUE(bytes == read_all(b)) << "two bakes of one scene and seed differ";
}

// Observers never change a run: summary.csv with --bake is summary.csv without it, byte for byte.
TEST(GltfBakeRun, SummaryIsTheSameWithAndWithoutTheBake) {
  UniqueDir dir("fragsim_bake");
  const std::string args = "compare --scene " + kScene + " --strategies none,edge-min,fade --csv ";
  const fs::path plain = dir.path() / "plain";
  const fs::path baked = dir.path() / "baked";
  ASSERT_EQ(run_fragsim(args + plain.string()).status, 0);
  const fragsim::test::Result r =
      run_fragsim(args + baked.string() + " --bake " + (dir.path() / "shot.glb").string());
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(read_all(plain / "summary.csv"), read_all(baked / "summary.csv"));
  EXPECT_EQ(read_all(plain / "steps.csv"), read_all(baked / "steps.csv"));
  // One file per strategy.
  for (const char* s : {"none", "edge-min", "fade"}) {
    EXPECT_TRUE(fs::exists(dir.path() / ("shot." + std::string(s) + ".glb"))) << s;
  }
}

TEST(GltfBakeRun, UnwritablePathIsOneLineAndNoFile) {
  UniqueDir dir("fragsim_bake");
  const fs::path missing = dir.path() / "no_such_folder" / "shot.glb";
  const fragsim::test::Result r =
      run_fragsim("run --scene " + kScene + " --bake " + missing.string());
  EXPECT_NE(r.status, 0);
  EXPECT_EQ(lines(r.out), 1) << r.out;
  EXPECT_NE(r.out.find("--bake"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(missing));
}

TEST(GltfBakeRun, WrongExtensionIsRefused) {
  UniqueDir dir("fragsim_bake");
  const fragsim::test::Result r =
      run_fragsim("run --scene " + kScene + " --bake " + (dir.path() / "shot.gltf").string());
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(lines(r.out), 1) << r.out;
  EXPECT_NE(r.out.find("--bake"), std::string::npos) << r.out;
}

// Over the limit: refused before the run when the animation alone is too large, and after it when
// the whole file is; either way one line and no file, not even a temporary one.
TEST(GltfBakeRun, OverTheSizeLimitIsOneLineAndNoFile) {
  UniqueDir dir("fragsim_bake");
  const std::string shot = (dir.path() / "shot.glb").string();
  // 125 pieces and the camera over 181 samples: 634 kB of keys alone.
  fragsim::test::Result r =
      run_fragsim("run --scene " + kScene + " --bake " + shot + " --bake-max-mb 0.5");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(lines(r.out), 1) << r.out;
  EXPECT_NE(r.out.find("--bake-max-mb"), std::string::npos) << r.out;
  // The keys fit in 0.65 MB, the JSON and meshes do not.
  r = run_fragsim("run --scene " + kScene + " --no-occlusion --bake " + shot +
                  " --bake-max-mb 0.65");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find("--bake-max-mb"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("nothing written"), std::string::npos) << r.out;
  EXPECT_TRUE(fs::is_empty(dir.path())) << "a file or temporary file was left";
  r = run_fragsim("run --scene " + kScene + " --bake " + shot + " --bake-max-mb lots");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(lines(r.out), 1) << r.out;
}

}  // namespace
