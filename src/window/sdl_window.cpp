#include "window/sdl_window.hpp"

#include <SDL.h>

namespace fragsim {
namespace {

// Radians of turn per pixel of mouse motion (a full turn in about 2,100 pixels).
constexpr double kMouseRadPerPx = 0.003;

enum Held { kForward, kBack, kRight, kLeft, kYawRight, kYawLeft, kPitchUp, kPitchDown };

int held_index(SDL_Scancode code) {
  switch (code) {
    case SDL_SCANCODE_W:
    case SDL_SCANCODE_UP:
      return kForward;
    case SDL_SCANCODE_S:
    case SDL_SCANCODE_DOWN:
      return kBack;
    case SDL_SCANCODE_D:
    case SDL_SCANCODE_RIGHT:
      return kRight;
    case SDL_SCANCODE_A:
    case SDL_SCANCODE_LEFT:
      return kLeft;
    case SDL_SCANCODE_E:
      return kYawRight;
    case SDL_SCANCODE_Q:
      return kYawLeft;
    case SDL_SCANCODE_R:
      return kPitchUp;
    case SDL_SCANCODE_F:
      return kPitchDown;
    default:
      return -1;
  }
}

bool command_for(SDL_Scancode code, PlayEvent& e) {
  if (code >= SDL_SCANCODE_1 && code <= SDL_SCANCODE_9) {
    e = {PlayCommand::kChooseStrategy, static_cast<int>(code - SDL_SCANCODE_1)};
    return true;
  }
  switch (code) {
    case SDL_SCANCODE_ESCAPE:
      e = {PlayCommand::kQuit, 0};
      return true;
    case SDL_SCANCODE_SPACE:
      e = {PlayCommand::kRestart, 0};
      return true;
    case SDL_SCANCODE_TAB:
      e = {PlayCommand::kNextStrategy, 0};
      return true;
    case SDL_SCANCODE_P:
      e = {PlayCommand::kPause, 0};
      return true;
    case SDL_SCANCODE_O:
      e = {PlayCommand::kOverlays, 0};
      return true;
    case SDL_SCANCODE_F12:
      e = {PlayCommand::kScreenshot, 0};
      return true;
    default:
      return false;
  }
}

// A variable set to an empty string names nothing, so it counts as unset, as a shell's `VAR=` does
// for most programs (SDL itself then probes its drivers, down to those that draw nowhere).
bool named_in_environment(const char* name) {
  const char* value = SDL_getenv(name);
  return value != nullptr && *value != '\0';
}

}  // namespace

SdlWindow::SdlWindow(int width_px, int height_px, const std::string& title) : title_(title) {
  // fragsim's own SIGINT/SIGTERM handling (io/atomic_file.hpp) stays in charge.
  SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
  // With no display named and no driver asked for, say so in one line before SDL probes its drivers
  // (and a Wayland library prints its own complaints).
  if (!named_in_environment("SDL_VIDEODRIVER") && !named_in_environment("DISPLAY") &&
      !named_in_environment("WAYLAND_DISPLAY")) {
    throw NoDisplay(
        "no display to open a window on (DISPLAY and WAYLAND_DISPLAY are unset); set DISPLAY, "
        "run under Xvfb, or name an SDL driver in SDL_VIDEODRIVER");
  }
  if (SDL_Init(SDL_INIT_VIDEO) != 0) {
    throw NoDisplay(std::string("no display to open a window on (SDL: ") + SDL_GetError() +
                    "); set DISPLAY, or run under Xvfb");
  }
  // Without a display SDL falls back on drivers that draw nowhere ("offscreen", "dummy"), and a
  // window nobody sees is no display, unless SDL_VIDEODRIVER asked for it.
  const char* driver = SDL_GetCurrentVideoDriver();
  const std::string name = driver ? driver : "";
  if (!named_in_environment("SDL_VIDEODRIVER") &&
      (name == "offscreen" || name == "dummy" || name.empty())) {
    SDL_Quit();
    throw NoDisplay("no display to open a window on (SDL found only its '" + name +
                    "' driver); set DISPLAY, or run under Xvfb");
  }
  window_ = SDL_CreateWindow(title.c_str(), SDL_WINDOWPOS_UNDEFINED, SDL_WINDOWPOS_UNDEFINED,
                             width_px, height_px, SDL_WINDOW_SHOWN);
  if (!window_) {
    const std::string why = SDL_GetError();
    SDL_Quit();
    throw NoDisplay("cannot open a window (SDL: " + why + ")");
  }
}

SdlWindow::~SdlWindow() {
  SDL_DestroyWindow(window_);
  SDL_Quit();
}

void SdlWindow::poll(long, std::vector<PlayEvent>& events, HeldControls& held) {
  SDL_Event ev;
  while (SDL_PollEvent(&ev)) {
    switch (ev.type) {
      case SDL_QUIT:
        events.push_back({PlayCommand::kQuit, 0});
        break;
      case SDL_KEYDOWN:
      case SDL_KEYUP: {
        const bool down = ev.type == SDL_KEYDOWN;
        const int i = held_index(ev.key.keysym.scancode);
        if (i >= 0) {
          down_[i] = down;
        } else if (down && !ev.key.repeat) {
          PlayEvent e;
          if (command_for(ev.key.keysym.scancode, e)) events.push_back(e);
        }
        break;
      }
      case SDL_MOUSEMOTION:
        if (ev.motion.state != 0) {
          held.mouse_yaw_rad += kMouseRadPerPx * ev.motion.xrel;
          held.mouse_pitch_rad -= kMouseRadPerPx * ev.motion.yrel;
        }
        break;
      case SDL_WINDOWEVENT:
        if (ev.window.event == SDL_WINDOWEVENT_FOCUS_LOST) {
          for (bool& d : down_) d = false;
        }
        break;
      default:
        break;
    }
  }
  const auto axis = [&](int plus, int minus) {
    return (down_[plus] ? 1.0 : 0.0) - (down_[minus] ? 1.0 : 0.0);
  };
  held.forward = axis(kForward, kBack);
  held.right = axis(kRight, kLeft);
  held.yaw = axis(kYawRight, kYawLeft);
  held.pitch = axis(kPitchUp, kPitchDown);
}

void SdlWindow::show_status(const std::string& text) {
  SDL_SetWindowTitle(window_, (title_ + " - " + text).c_str());
}

void SdlWindow::present(const Image& frame) {
  SDL_Surface* target = SDL_GetWindowSurface(window_);
  if (!target) return;  // minimised or being resized, so nothing to draw on this time
  // The image's RGB rows as a surface without a copy; the blit converts to the window's format.
  SDL_Surface* src = SDL_CreateRGBSurfaceWithFormatFrom(
      const_cast<std::uint8_t*>(frame.bytes().data()), frame.width(), frame.height(), 24,
      3 * frame.width(), SDL_PIXELFORMAT_RGB24);
  if (!src) return;
  SDL_BlitSurface(src, nullptr, target, nullptr);
  SDL_FreeSurface(src);
  SDL_UpdateWindowSurface(window_);
}

}  // namespace fragsim
