// The built-in bitmap font: text measured and drawn inside its box, descenders below the baseline.

#include "render/bitmap_font.hpp"

#include <gtest/gtest.h>

#include <string>

#include "render/image.hpp"

namespace fragsim {
namespace {

TEST(BitmapFont, DrawsInsideItsBoxAndMeasuresIt) {
  EXPECT_EQ(text_width_px("t = 0.30 s", 1), 10 * kGlyphAdvancePx - 1);
  EXPECT_EQ(text_width_px("ab", 2), 2 * (2 * kGlyphAdvancePx - 1));
  for (const char c : std::string("0123456789abcdefghijklmnopqrstuvwxyz-.= s")) {
    EXPECT_TRUE(has_glyph(c)) << c;
  }
  Image img(40, 20);
  draw_text(img, 3, 2, "edge-min", {255, 255, 255}, 1);
  int lit = 0;
  for (int y = 0; y < img.height(); ++y) {
    for (int x = 0; x < img.width(); ++x) {
      if (img.at(x, y) == Rgb{255, 255, 255}) {
        ++lit;
        EXPECT_GE(x, 3);
        EXPECT_LT(x, 3 + text_width_px("edge-min"));
        EXPECT_GE(y, 2);
        EXPECT_LT(y, 2 + kGlyphHeightPx);
      }
    }
  }
  EXPECT_GT(lit, 40);
  // "g" has a descender: something is drawn below the baseline (row 7 of the glyph).
  Image g(6, kGlyphHeightPx);
  draw_text(g, 0, 0, "g", {255, 255, 255});
  bool below = false;
  for (int x = 0; x < 5; ++x) below = below || g.at(x, 8) == Rgb{255, 255, 255};
  EXPECT_TRUE(below);
}

}  // namespace
}  // namespace fragsim
