#pragma once
// One run: a scene, a strategy and the observers that watch it. The loop is the only place where
// the three meet; the strategy answers before each physics step, the observers look after it.

#include <span>

#include "sim/run_observer.hpp"
#include "sim/scene.hpp"
#include "strategies/strategy.hpp"

namespace fragsim {

class CameraMotion;

struct RunTotals {
  int steps = 0;
  double physics_s = 0.0;
  double strategy_s = 0.0;
  double wall_s = 0.0;          // the whole run, observers included
  long ode_messages = 0;        // warnings ODE printed during the run
  int nonfinite_fragments = 0;  // fragments whose state became NaN or infinite (then frozen)
};

RunTotals simulate(const Scene& scene, Strategy& strategy,
                   std::span<RunObserver* const> observers = {});
// The same with the camera's motion given by the caller instead of made from camera.mode (a
// camera steered live, src/play). Step k asks for its pose and velocity at k dt, then, as it ends,
// at (k + 1) dt; nothing later.
RunTotals simulate(const Scene& scene, Strategy& strategy, const CameraMotion& camera,
                   std::span<RunObserver* const> observers = {});

// Test-only (tests/cli/output_safety_test.cpp), so that a signal lands at a known point of a run
// instead of after a guessed time. Reads FRAGSIM_TEST_RAISE_AT_STEP=N and
// FRAGSIM_TEST_RAISE_SIGNAL=INT|TERM|HUP|KILL once; then the N-th step this process simulates,
// counted over all its runs (a forked worker goes on from its parent's count), sends the signal to
// the process that called this (a worker's signal reaches its parent, as a user's would), or with
// FRAGSIM_TEST_RAISE_IN=self to the process that counted it (a worker that crashes). Without
// both variables it does nothing. Only fragsim's main calls it.
void arm_test_signal_from_environment();

}  // namespace fragsim
