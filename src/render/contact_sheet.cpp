#include "render/contact_sheet.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render/bitmap_font.hpp"

namespace fragsim {

namespace {

constexpr Rgb kBackground{28, 30, 34};
constexpr Rgb kEmptyCell{60, 62, 68};
constexpr Rgb kText{236, 236, 236};
constexpr int kScale = 2;  // text at twice the font's size
constexpr int kMargin = 10;
constexpr int kGap = 4;

std::string time_label(double t_s) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "t = %.2f s", t_s);
  return buf;
}

}  // namespace

std::vector<int> default_sheet_steps(int step_count) {
  std::vector<int> steps;
  for (const double share : {0.10, 0.20, 0.25, 0.35}) {
    steps.push_back(static_cast<int>(std::lround(share * std::max(0, step_count))));
  }
  steps.erase(std::unique(steps.begin(), steps.end()), steps.end());
  return steps;
}

Image contact_sheet(const Scene& scene, const FrameRecorder& recorder,
                    const std::vector<std::string>& strategies, const std::vector<int>& steps,
                    const SheetStyle& style) {
  const int cell_w = std::max(1, style.cell_width_px);
  const int cell_h = style.cell_height_px > 0
                         ? style.cell_height_px
                         : std::max(1, static_cast<int>(std::lround(cell_w / scene.camera.aspect)));
  const int text_h = kGlyphHeightPx * kScale;
  int label_w = text_width_px(scene.name, kScale);
  for (const std::string& s : strategies) label_w = std::max(label_w, text_width_px(s, kScale));
  const int x0 = kMargin + label_w + kMargin;  // the first column's left edge
  const int y0 = kMargin + text_h + kMargin;   // the first row's top edge
  const int cols = static_cast<int>(steps.size());
  const int rows = static_cast<int>(strategies.size());
  const int width = x0 + cols * (cell_w + kGap) - (cols > 0 ? kGap : 0) + kMargin;
  const int height = y0 + rows * (cell_h + kGap) - (rows > 0 ? kGap : 0) + kMargin;
  Image sheet(width, height, kBackground);
  draw_text(sheet, kMargin, kMargin, scene.name, kText, kScale);

  FrameStyle frame_style;
  frame_style.width_px = cell_w;
  frame_style.height_px = cell_h;
  frame_style.overlays = style.overlays;
  FrameRenderer renderer(scene, frame_style);
  for (int c = 0; c < cols; ++c) {
    const int x = x0 + c * (cell_w + kGap);
    const std::string label = time_label(steps[c] * scene.sim.dt_s);
    draw_text(sheet, x + (cell_w - text_width_px(label, kScale)) / 2, kMargin, label, kText,
              kScale);
  }
  for (int r = 0; r < rows; ++r) {
    const int y = y0 + r * (cell_h + kGap);
    draw_text(sheet, kMargin, y + (cell_h - text_h) / 2, strategies[r], kText, kScale);
    for (int c = 0; c < cols; ++c) {
      const int x = x0 + c * (cell_w + kGap);
      if (const RecordedFrame* f = recorder.frame(strategies[r], steps[c])) {
        sheet.blit(renderer.render(f->view()), x, y);
      } else {
        sheet.fill_rect(x, y, x + cell_w, y + cell_h, kEmptyCell);
      }
    }
  }
  return sheet;
}

}  // namespace fragsim
