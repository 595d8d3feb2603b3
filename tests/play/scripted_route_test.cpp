// The benchmark's scripted route (play/scripted_route.cpp): a four-second loop of held keys by the
// step's second, the same whatever was held before. By hand at 60 steps a second: steps 0-59
// forward, 60-119 forward and right, 120-179 left turning left, 180-239 back turning right.

#include "play/scripted_route.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace fragsim {
namespace {

HeldControls at(ScriptedRoute& route, long step) {
  std::vector<PlayEvent> events;
  HeldControls held;
  held.pitch = 1.0;  // whatever was held is replaced
  held.mouse_yaw_rad = 0.3;
  route.poll(step, events, held);
  EXPECT_TRUE(events.empty()) << step;
  EXPECT_EQ(held.pitch, 0.0) << step;
  EXPECT_EQ(held.mouse_yaw_rad, 0.0) << step;
  return held;
}

TEST(ScriptedRoute, FourSecondLoopOfHeldKeys) {
  ScriptedRoute route(1.0 / 60.0);
  EXPECT_FALSE(route.paced());
  for (long step : {0L, 59L, 240L}) {
    const HeldControls h = at(route, step);
    EXPECT_EQ(h.forward, 1.0) << step;
    EXPECT_EQ(h.right, 0.0) << step;
    EXPECT_EQ(h.yaw, 0.0) << step;
  }
  for (long step : {60L, 119L}) {
    const HeldControls h = at(route, step);
    EXPECT_EQ(h.forward, 1.0) << step;
    EXPECT_EQ(h.right, 1.0) << step;
  }
  for (long step : {120L, 179L}) {
    const HeldControls h = at(route, step);
    EXPECT_EQ(h.forward, 0.0) << step;
    EXPECT_EQ(h.right, -1.0) << step;
    EXPECT_EQ(h.yaw, -0.5) << step;
  }
  for (long step : {180L, 239L, 479L}) {
    const HeldControls h = at(route, step);
    EXPECT_EQ(h.forward, -1.0) << step;
    EXPECT_EQ(h.right, 0.0) << step;
    EXPECT_EQ(h.yaw, 0.5) << step;
  }
  // Another step size keeps the seconds: at 1/30 s, step 30 is the second second.
  ScriptedRoute coarse(1.0 / 30.0);
  EXPECT_EQ(at(coarse, 29).right, 0.0);
  EXPECT_EQ(at(coarse, 30).right, 1.0);
}

}  // namespace
}  // namespace fragsim
