#pragma once
// A player that is a script, the benchmark's front end (`fragsim play --bench-frames N`). It flies
// a fixed route by the step count, toward the blast, strafing right, then left while turning, and
// back, each for a second; nothing is shown and nothing waits for the clock, so the same loop as
// the window's runs as fast as the machine allows.

#include "play/play_frontend.hpp"

namespace fragsim {

class ScriptedRoute final : public PlayFrontend {
 public:
  explicit ScriptedRoute(double dt_s) : dt_s_(dt_s) {}
  void poll(long step, std::vector<PlayEvent>& events, HeldControls& held) override;
  void present(const Image&) override {}
  bool paced() const override { return false; }

 private:
  double dt_s_;
};

}  // namespace fragsim
