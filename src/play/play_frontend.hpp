#pragma once
// What a live session needs from whoever plays it, the window (sdl_window.hpp) or a script (the
// benchmark's, scripted_route.hpp). The session never sees a device.

#include <string>
#include <vector>

#include "play/flight_controls.hpp"
#include "render/image.hpp"

namespace fragsim {

enum class PlayCommand {
  kQuit,            // Esc, the window closed
  kRestart,         // Space replays the explosion, aimed at where the camera is
  kNextStrategy,    // Tab
  kChooseStrategy,  // 1-9 pick PlayEvent::strategy, from 0
  kPause,           // P pauses or resumes
  kOverlays,        // O toggles the overlays
  kScreenshot,      // F12 saves the frame as a PNG file
};

struct PlayEvent {
  PlayCommand command = PlayCommand::kQuit;
  int strategy = 0;
};

class PlayFrontend {
 public:
  virtual ~PlayFrontend() = default;
  // Appends what was pressed since the last call, in order, and updates what is held. `step` is
  // the number of steps simulated in this session so far (a script's clock).
  virtual void poll(long step, std::vector<PlayEvent>& events, HeldControls& held) = 0;
  virtual void present(const Image& frame) = 0;
  // Whether simulated time follows the clock (a person watches) or runs as fast as it goes.
  virtual bool paced() const = 0;
  // Where the flight is ("flight 1, none, 1.2 s"), each time that text changes. A window shows it
  // in its title, where a script driving the window reads simulated time (play_window_test.sh).
  virtual void show_status(const std::string& /*text*/) {}
};

}  // namespace fragsim
