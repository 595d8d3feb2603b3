#pragma once
// One run: a scene, a strategy and the observers that watch it. The loop is the only place where
// the three meet; the strategy answers before each physics step, the observers look after it.

#include <span>

#include "sim/run_observer.hpp"
#include "sim/scene.hpp"
#include "strategies/strategy.hpp"

namespace fragsim {

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

}  // namespace fragsim
