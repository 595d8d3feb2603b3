#pragma once
// Which ballistic path stands for a fragment's flight. A strategy predicts with one of them, and
// the time-against-error bench measures the strategy's error against the one it uses.

namespace fragsim {

enum class Predictor {
  kThesis,    // (3.1) with the velocity read from the physics.
  kDiscrete,  // ODE's semi-implicit Euler, the parabola with velocity V + g dt/2.
};

}  // namespace fragsim
