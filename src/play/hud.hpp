#pragma once
// The line over the picture while playing shows the strategy, the flight's time, near-plane
// fragments and camera hits so far, current candidates, the strategy's milliseconds per step, and
// whether simulated time runs slower than the clock. A second line at the bottom shows messages
// (the replay command of the last recording) and the keys.

#include <string>

#include "render/image.hpp"

namespace fragsim {

struct HudState {
  std::string strategy;
  double t_s = 0.0;
  int near_fragments = 0;
  int camera_hits = 0;
  int candidates = 0;
  double strategy_ms = 0.0;
  // Simulated seconds per wall-clock second over the last moments, 1 in real time, less when the
  // machine cannot keep up (steps are never dropped).
  double time_rate = 1.0;
  bool paused = false;
  std::string message;  // the keys if empty
};

inline constexpr Rgb kHudBand{0, 0, 0};
inline constexpr Rgb kHudText{255, 255, 255};
inline constexpr Rgb kHudWarning{255, 200, 0};
inline constexpr int kHudBandPx = 13;  // a glyph (9) and a 2-pixel margin above and below

// The top line's text.
std::string hud_line(const HudState& hud);
// Draws both lines on dark bands across the top and bottom of `image`.
void draw_hud(Image& image, const HudState& hud);

}  // namespace fragsim
