#include "play/hud.hpp"

#include "io/number_format.hpp"
#include "render/bitmap_font.hpp"

namespace fragsim {
namespace {

constexpr const char* kKeys =
    "wasd move  q/e/r/f or drag turn  space restart  tab/1-9 strategy  p pause  o overlays  "
    "f12 png  esc quit";

// Below this share of real time the line says the simulation is slowed.
constexpr double kSlowRate = 0.98;

}  // namespace

std::string hud_line(const HudState& hud) {
  std::string line = hud.strategy + "  t " + fixed_text(hud.t_s, 2) + " s  near " +
                     std::to_string(hud.near_fragments) + "  cam " +
                     std::to_string(hud.camera_hits) + "  cand " + std::to_string(hud.candidates) +
                     "  strat " + fixed_text(hud.strategy_ms, 3) + " ms";
  if (hud.time_rate < kSlowRate) {
    line += "  slowed to " + fixed_text(hud.time_rate, 2) + "x real time";
  }
  if (hud.paused) line += "  paused";
  return line;
}

void draw_hud(Image& image, const HudState& hud) {
  const int w = image.width();
  const int h = image.height();
  image.fill_rect(0, 0, w, kHudBandPx, kHudBand);
  const bool slow = hud.time_rate < kSlowRate;
  draw_text(image, 3, 2, hud_line(hud), slow ? kHudWarning : kHudText);
  image.fill_rect(0, h - kHudBandPx, w, h, kHudBand);
  draw_text(image, 3, h - kHudBandPx + 2, hud.message.empty() ? kKeys : hud.message, kHudText);
}

}  // namespace fragsim
