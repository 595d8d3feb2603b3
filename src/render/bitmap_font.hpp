#pragma once
// A tiny built-in bitmap font for labels, with glyphs 5 pixels wide, 7 above the baseline and 2
// below it (the descenders of g j p q y). Digits, lower-case letters (upper case is drawn as lower
// case), space and - . = : / ( ) % _ +; other characters advance without drawing.

#include <string_view>

#include "render/image.hpp"

namespace fragsim {

inline constexpr int kGlyphWidthPx = 5;
inline constexpr int kGlyphHeightPx = 9;   // 7 above the baseline, 2 below
inline constexpr int kGlyphAdvancePx = 6;  // a one-pixel gap between glyphs

bool has_glyph(char c);
// Width of `text` at `scale` (each font pixel a scale x scale square), without a trailing gap.
int text_width_px(std::string_view text, int scale = 1);
// Draws `text` with its top-left corner at (x, y), clipped to the image.
void draw_text(Image& image, int x, int y, std::string_view text, Rgb colour, int scale = 1);

}  // namespace fragsim
