#pragma once
// One box in free flight or dropped, cases whose positions and first contact are worked out by
// hand (tests/experiments: the accuracy probe and the time-against-error bench).

#include "sim/scene.hpp"
#include "support/test_scenes.hpp"

namespace fragsim::test {

inline constexpr double kG = 9.81;

// One box thrown up and away from a still camera, no ground: it never touches anything.
inline Scene away_flight() {
  Scene s = test::single_fragment({0.0, 1.6, -10.0}, 8.0);
  s.explosion.offset_m = {0.0, -1.0, 1.0};  // radial push up and away from the camera
  s.sim.gravity_mps2 = {0.0, -kG, 0.0};
  s.sim.duration_s = 1.0;
  return s;
}

// One box at rest 2 m up, dropped onto the ground.
inline Scene drop() {
  Scene s = test::single_fragment({0.0, 2.0, -10.0}, 0.0);
  s.sim.gravity_mps2 = {0.0, -kG, 0.0};
  s.ground.enabled = true;
  s.sim.duration_s = 1.0;
  return s;
}

}  // namespace fragsim::test
