// `fragsim render` and `fragsim compare --sheet` through the executable: the same frames on a
// rerun, overlays drawn, and every bad option a one-line usage error.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "render/bitmap_font.hpp"
#include "render/frame_renderer.hpp"
#include "render/image.hpp"
#include "support/run_fragsim.hpp"

namespace fragsim {
namespace {

namespace fs = std::filesystem;

using test::Result;
Result fragsim(const std::string& args) {
  return test::run_fragsim(args);
}

std::string read_all(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

int lines(const std::string& s) {
  int n = 0;
  for (char c : s) n += c == '\n';
  return n;
}

const std::string kThesis125 = "--scene " + std::string(FRAGSIM_DATA_DIR) + "/scenes/thesis125.ini";
const std::string kSmall = kThesis125 + " --simulation.duration_s 0.5";  // 30 steps

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::path(::testing::TempDir()) / name;
  fs::remove_all(d);
  return d;
}

TEST(RenderCommand, WritesTheSameFramesTwice) {
  const fs::path a = fresh_dir("fragsim_render_a");
  const fs::path b = fresh_dir("fragsim_render_b");
  // The whole run (3 s), so `edge` has candidates (46 at first) and forces to draw.
  const std::string args = "render " + kThesis125 +
                           " --strategy edge --steps 0:30:10 --size 160x90 "
                           "--overlays candidates,forces,central,cuts --out ";
  const Result ra = fragsim(args + a.string());
  ASSERT_EQ(ra.status, 0) << ra.out;
  ASSERT_EQ(fragsim(args + b.string()).status, 0);
  for (const char* name :
       {"frame_00000.png", "frame_00010.png", "frame_00020.png", "frame_00030.png"}) {
    const std::string png = read_all(a / name);
    ASSERT_FALSE(png.empty()) << name;
    EXPECT_EQ(png, read_all(b / name)) << name;
    EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
    const Image img = decode_png(png);
    EXPECT_EQ(img.width(), 160);
    EXPECT_EQ(img.height(), 90);
    bool outlined = false;
    for (int y = 0; y < img.height(); ++y) {
      for (int x = 0; x < img.width(); ++x) outlined = outlined || img.at(x, y) == kCandidateColour;
    }
    // Step 0 is the explosion: no strategy step has run yet, so no candidates.
    EXPECT_EQ(outlined, std::string(name) != "frame_00000.png") << name;
  }
  const Image first = read_png((a / "frame_00000.png").string());
  EXPECT_GT(first.at(2, 2).b, first.at(2, 2).r + 40);  // sky in the corner
  int files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(a)) ++files;
  EXPECT_EQ(files, 4);
  // The frames of a rerun into the same folder need --force.
  const Result again = fragsim(args + a.string());
  EXPECT_EQ(again.status, 2);
  EXPECT_EQ(lines(again.out), 1) << again.out;
  EXPECT_NE(again.out.find("--force"), std::string::npos) << again.out;
  EXPECT_EQ(fragsim(args + a.string() + " --force").status, 0);
}

TEST(RenderCommand, BadOptionsAreOneLineUsageErrors) {
  const fs::path dir = fresh_dir("fragsim_render_bad");
  const std::string out = " --out " + dir.string();
  const std::vector<std::pair<std::string, std::string>> cases{
      {"--size 640", "--size"},
      {"--size 8x8", "--size"},
      {"--size 640x360x2", "--size"},
      {"--steps 5:2", "--steps"},
      {"--steps 0:31", "--steps"},  // 0.5 s is 30 steps
      {"--steps 0:10:0", "--steps"},
      {"--steps a:b", "--steps"},
      {"--overlays candidates,sparkles", "sparkles"},
      {"--strategy teleport", "teleport"},
  };
  for (const auto& [opt, named] : cases) {
    const Result r = fragsim("render " + kSmall + " " + opt + out);
    EXPECT_EQ(r.status, 2) << opt << ": " << r.out;
    EXPECT_EQ(lines(r.out), 1) << opt << ": " << r.out;
    EXPECT_NE(r.out.find(named), std::string::npos) << opt << ": " << r.out;
  }
  EXPECT_EQ(fragsim("render " + kSmall).status, 2);  // no --out
  EXPECT_FALSE(fs::exists(dir));                     // refused before anything was created
}

TEST(RenderCommand, WritesOneRowPerStrategyAndChecksItsOptions) {
  const fs::path dir = fresh_dir("fragsim_sheet");
  fs::create_directories(dir);
  const fs::path sheet = dir / "sheet.png";
  const Result r = fragsim("compare " + kSmall + " --strategies none,edge-min --sheet " +
                           sheet.string() + " --sheet-steps 5,15,25");
  ASSERT_EQ(r.status, 0) << r.out;
  const Image img = read_png(sheet.string());
  // 3 cells of 320 wide and 180 high (16:9), in the layout of contact_sheet.cpp.
  EXPECT_EQ(img.width(), 10 + text_width_px("thesis125", 2) + 10 + 3 * 320 + 2 * 4 + 10);
  EXPECT_EQ(img.height(), 10 + 2 * kGlyphHeightPx + 10 + 2 * 180 + 4 + 10);

  const Result bad =
      fragsim("compare " + kSmall + " --sheet " + sheet.string() + " --sheet-steps 5,99");
  EXPECT_EQ(bad.status, 2);
  EXPECT_EQ(lines(bad.out), 1) << bad.out;
  EXPECT_NE(bad.out.find("--sheet-steps"), std::string::npos) << bad.out;
  const Result no_dir = fragsim("compare " + kSmall + " --sheet " + (dir / "no/s.png").string());
  EXPECT_EQ(no_dir.status, 2);
  EXPECT_EQ(lines(no_dir.out), 1) << no_dir.out;
  EXPECT_EQ(fragsim("compare " + kSmall + " --sheet-steps 1,2").status, 2);
}

}  // namespace
}  // namespace fragsim
