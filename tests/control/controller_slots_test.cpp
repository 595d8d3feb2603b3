// The table behind fragsim_controller_id (api/controller_slots.cpp): an id finds its controller
// until it is removed, never after; a reused slot gets a new generation, so the old id stays dead.
// The controllers are stand-in addresses: the table stores and returns them, never follows them.

#include "control/api/controller_slots.hpp"

#include <gtest/gtest.h>

namespace {

using fragsim::control::add_controller;
using fragsim::control::Controller;
using fragsim::control::find_controller;
using fragsim::control::remove_controller;

int stand_in_a = 0;
int stand_in_b = 0;
Controller* const kA = reinterpret_cast<Controller*>(&stand_in_a);
Controller* const kB = reinterpret_cast<Controller*>(&stand_in_b);

TEST(ControllerSlots, AnIdFindsItsControllerUntilRemoved) {
  const fragsim_controller_id id = add_controller(kA);
  ASSERT_NE(id.index1, 0u);
  EXPECT_GE(id.generation, 1u);  // no live id is all zero
  EXPECT_EQ(find_controller(id), kA);
  EXPECT_EQ(remove_controller(id), kA);
  EXPECT_EQ(find_controller(id), nullptr);
  EXPECT_EQ(remove_controller(id), nullptr);  // removed once only
}

TEST(ControllerSlots, AReusedSlotHasANewGenerationAndTheOldIdStaysDead) {
  const fragsim_controller_id first = add_controller(kA);
  ASSERT_EQ(remove_controller(first), kA);
  // The slot just freed is the next one handed out: removal made generation + 1 dead, so the new
  // controller's is generation + 2.
  const fragsim_controller_id second = add_controller(kB);
  EXPECT_EQ(second.index1, first.index1);
  EXPECT_EQ(second.generation, first.generation + 2);
  EXPECT_EQ(find_controller(first), nullptr);
  EXPECT_EQ(remove_controller(first), nullptr);
  EXPECT_EQ(find_controller(second), kB);
  // The dead generation in between finds nothing either.
  EXPECT_EQ(find_controller({first.index1, first.generation + 1}), nullptr);
  EXPECT_EQ(remove_controller(second), kB);
}

TEST(ControllerSlots, NullAndOutOfRangeIdsFindNothing) {
  EXPECT_EQ(find_controller({0, 0}), nullptr);
  EXPECT_EQ(find_controller({0, 1}), nullptr);
  EXPECT_EQ(find_controller({FRAGSIM_MAX_CONTROLLERS + 1, 1}), nullptr);
  EXPECT_EQ(remove_controller({0, 1}), nullptr);
  EXPECT_EQ(remove_controller({FRAGSIM_MAX_CONTROLLERS + 1, 1}), nullptr);
  // The last slot: never handed out in a test program (its chunk does not exist).
  EXPECT_EQ(find_controller({FRAGSIM_MAX_CONTROLLERS, 1}), nullptr);
}

}  // namespace
