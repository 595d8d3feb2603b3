#pragma once
// A live session of `fragsim play` is flights one after another, each a Run (sim/run.hpp) of the
// scene's explosion stepped by a plain loop that reads the front end's input, steers the camera
// (steered_camera.hpp), steps the run and draws it with the software renderer and the HUD. Space
// restarts the flight (the same seed, the blast aimed at where the camera is then), Tab or a
// number switches the strategy and restarts, P pauses, O toggles the overlays, Esc quits. Every
// step is simulated at the scene's dt. When the machine cannot keep up simulated time slows (the
// HUD says so) and no step is dropped, so the recorded flight (flight_record.hpp) replays exactly.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "play/flight_controls.hpp"
#include "play/flight_record.hpp"
#include "play/play_frontend.hpp"
#include "render/frame_renderer.hpp"
#include "sim/scene.hpp"

namespace fragsim {

struct PlayOptions {
  std::string strategy = "edge-min";
  std::string record;         // --record FILE; if empty, play-NNN.csv in record_folder
  std::string record_folder;  // the working folder if empty
  bool record_flights = true;
  std::string screenshot_folder;  // F12's play-shot-NNN.png go here; the working folder if empty
  FrameStyle style;               // the size, and the overlays O toggles
  long max_steps = 0;             // stop after this many steps in all (the benchmark); 0 for never
};

// One flight as it ended, what the HUD showed last and where it was recorded.
struct FlightReport {
  int flight = 0;  // from 1
  std::string strategy;
  int steps = 0;
  double t_s = 0.0;
  int near_fragments = 0;
  int camera_hits = 0;
  std::optional<RecordPaths> recorded;  // none for a flight of no step, or without recording
};

// Per drawn frame, in milliseconds, the parts and the whole (the steps since the last frame,
// metrics, input, drawing and presenting; not the wait for the clock).
struct FrameTimes {
  std::vector<double> physics_ms;
  std::vector<double> strategy_ms;
  std::vector<double> draw_ms;  // the scene and the HUD into the image
  std::vector<double> present_ms;
  std::vector<double> frame_ms;
};

class PlaySession {
 public:
  // Throws InputError for an unknown strategy or bad parameters, before anything runs.
  PlaySession(const Scene& scene, PlayOptions options, PlayFrontend& frontend);

  // Called as each flight ends (a restart, a switch, the quit), after it was recorded; and with
  // a line to show the player (a screenshot written).
  std::function<void(const FlightReport&)> on_flight;
  std::function<void(const std::string&)> on_message;

  // Plays until the front end quits (or max_steps). Throws std::runtime_error if a recording or
  // a screenshot cannot be written.
  void run();

  const FrameTimes& times() const { return times_; }
  const std::vector<std::string>& strategies() const { return strategies_; }

 private:
  // One flight's loop, which reads the input, steps the run and draws.
  class Flight;

  Scene flight_scene_;  // the scene as flown (object placed, aim present, up to an hour)
  PlayOptions options_;
  PlayFrontend& frontend_;
  std::vector<std::string> strategies_;
  std::size_t current_ = 0;
  FlightControls controls_;
  HeldControls held_;
  bool overlays_ = true;
  long session_steps_ = 0;
  int flights_ = 0;
  int recorded_ = 0;     // flights recorded (a flight of no step is not)
  std::string message_;  // shown on the HUD's bottom line until the next flight's end
  FrameTimes times_;
};

}  // namespace fragsim
