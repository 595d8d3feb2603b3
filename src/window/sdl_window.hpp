#pragma once
// The play window. SDL2 (Debian's libsdl2) opens it, shows the session's frames and maps the
// keyboard and mouse to the session's controls. This is the only file that includes SDL.

#include <stdexcept>
#include <string>

#include "play/play_frontend.hpp"

struct SDL_Window;

namespace fragsim {

// No display to open a window on (no DISPLAY, no video driver); the message is one line.
class NoDisplay : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class SdlWindow final : public PlayFrontend {
 public:
  // Opens a width x height window titled `title`. Throws NoDisplay.
  SdlWindow(int width_px, int height_px, const std::string& title);
  ~SdlWindow() override;
  SdlWindow(const SdlWindow&) = delete;
  SdlWindow& operator=(const SdlWindow&) = delete;

  // Keys: WASD or the arrows move, Q/E/R/F turn, the mouse turns while a button is held; Space,
  // Tab, 1-9, P, O, F12 and Esc are commands (play_frontend.hpp). A key held when the window
  // loses focus counts as released.
  void poll(long step, std::vector<PlayEvent>& events, HeldControls& held) override;
  void present(const Image& frame) override;
  bool paced() const override { return true; }
  // The title becomes "TITLE - text".
  void show_status(const std::string& text) override;

 private:
  SDL_Window* window_ = nullptr;
  std::string title_;
  // What each movement key holds, as +1 / -1 pairs summed into HeldControls each poll.
  bool down_[8] = {};
};

}  // namespace fragsim
