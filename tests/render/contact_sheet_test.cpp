// The contact sheet: its default columns, its layout, and each cell the recorded frame.

#include "render/contact_sheet.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "experiments/evaluation.hpp"
#include "render/bitmap_font.hpp"
#include "render/frame_recorder.hpp"
#include "render/frame_renderer.hpp"
#include "render/image.hpp"
#include "support/test_scenes.hpp"

namespace fragsim {
namespace {

TEST(ContactSheet, DefaultStepsAndCellsAreTheFrames) {
  EXPECT_EQ(default_sheet_steps(180), (std::vector<int>{18, 36, 45, 63}));
  EXPECT_EQ(default_sheet_steps(2), (std::vector<int>{0, 1}));

  Scene scene = test::single_fragment({0.0, 1.6, -3.0}, 2.0);
  scene.ground.enabled = true;
  scene.ground.height_m = 0.0;
  FrameRecorder rec({5, 20});
  EvaluationOptions opts;
  opts.occlusion = false;
  opts.extra = {&rec};
  evaluate(scene, "none", opts);
  evaluate(scene, "edge", opts);
  SheetStyle style;
  style.cell_width_px = 64;
  style.overlays = {};
  const std::vector<std::string> rows{"none", "edge", "wall"};  // wall did not run: empty cells
  const Image sheet = contact_sheet(scene, rec, rows, {5, 20}, style);
  const int cell_h = static_cast<int>(std::lround(64 / scene.camera.aspect));
  // The layout of contact_sheet.cpp: margins of 10, gaps of 4, text twice the font's size.
  const int x0 = 10 + text_width_px("single", 2) + 10;
  const int y0 = 10 + 2 * kGlyphHeightPx + 10;
  EXPECT_EQ(sheet.width(), x0 + 2 * 64 + 4 + 10);
  EXPECT_EQ(sheet.height(), y0 + 3 * cell_h + 2 * 4 + 10);
  // The cell of edge at step 20 is that frame, drawn at the cell's size.
  FrameStyle fs;
  fs.width_px = 64;
  fs.height_px = cell_h;
  const Image frame = FrameRenderer(scene, fs).render(rec.frame("edge", 20)->view());
  const int cx = x0 + 64 + 4;
  const int cy = y0 + cell_h + 4;
  for (int y = 0; y < cell_h; ++y) {
    for (int x = 0; x < 64; ++x) ASSERT_EQ(sheet.at(cx + x, cy + y), frame.at(x, y));
  }
}

}  // namespace
}  // namespace fragsim
