// The line over the picture while playing (play/hud.cpp): its text to the character, and the two
// bands drawn with the warning colour when simulated time runs slow.

#include "play/hud.hpp"

#include <gtest/gtest.h>

namespace fragsim {
namespace {

HudState state() {
  HudState h;
  h.strategy = "edge-min";
  h.t_s = 1.5;
  h.near_fragments = 2;
  h.camera_hits = 0;
  h.candidates = 17;
  h.strategy_ms = 0.125;
  return h;
}

TEST(Hud, LineShowsTheCountsWithFixedDecimals) {
  HudState h = state();
  EXPECT_EQ(hud_line(h), "edge-min  t 1.50 s  near 2  cam 0  cand 17  strat 0.125 ms");
  h.time_rate = 0.98;  // the threshold itself is not slowed
  EXPECT_EQ(hud_line(h), "edge-min  t 1.50 s  near 2  cam 0  cand 17  strat 0.125 ms");
  h.time_rate = 0.5;
  h.paused = true;
  EXPECT_EQ(hud_line(h),
            "edge-min  t 1.50 s  near 2  cam 0  cand 17  strat 0.125 ms  slowed to 0.50x real "
            "time  paused");
}

// Counts the pixels of colour c in rows [y0, y1).
int pixels(const Image& image, int y0, int y1, Rgb c) {
  int n = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = 0; x < image.width(); ++x) n += image.at(x, y) == c;
  }
  return n;
}

TEST(Hud, DrawsBothBandsAndWarnsInItsOwnColour) {
  const Rgb grey{90, 90, 90};
  Image image(320, 60, grey);
  HudState h = state();
  draw_hud(image, h);
  // The top band (rows 0 to 12) and the bottom one (47 to 59): dark with white text; between them
  // the picture is untouched.
  EXPECT_EQ(pixels(image, 0, 1, kHudBand), 320);  // the margin above the glyphs
  EXPECT_GT(pixels(image, 0, kHudBandPx, kHudText), 0);
  EXPECT_EQ(pixels(image, 0, kHudBandPx, kHudWarning), 0);
  EXPECT_EQ(pixels(image, kHudBandPx, 60 - kHudBandPx, grey), 320 * (60 - 2 * kHudBandPx));
  EXPECT_GT(pixels(image, 60 - kHudBandPx, 60, kHudText), 0);
  EXPECT_EQ(pixels(image, 59, 60, kHudBand), 320);
  h.time_rate = 0.5;
  draw_hud(image, h);
  EXPECT_GT(pixels(image, 0, kHudBandPx, kHudWarning), 0);
  EXPECT_EQ(pixels(image, 0, kHudBandPx, kHudText), 0);
}

}  // namespace
}  // namespace fragsim
