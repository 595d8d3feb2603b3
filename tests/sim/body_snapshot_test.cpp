// The state World::step takes an exact step again from (sim/body_snapshot.cpp): every awake body
// put back as it was, to the bit, and enabled again; a sleeping body is not saved, so left alone.

#include "sim/body_snapshot.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace fragsim {
namespace {

void expect_vec(const dReal* v, dReal x, dReal y, dReal z) {
  EXPECT_EQ(v[0], x);
  EXPECT_EQ(v[1], y);
  EXPECT_EQ(v[2], z);
}

TEST(BodySnapshot, RestoresEveryAwakeBodyAndLeavesSleepersOut) {
  dInitODE2(0);
  const dWorldID world = dWorldCreate();
  dWorldSetGravity(world, 0.0, -9.81, 0.0);
  const dBodyID a = dBodyCreate(world);
  const dBodyID b = dBodyCreate(world);
  const dBodyID asleep = dBodyCreate(world);
  dBodySetPosition(a, 1.0, 2.0, 3.0);
  dBodySetLinearVel(a, 0.5, -0.25, 4.0);
  dBodySetAngularVel(a, 2.0, 0.0, -2.0);
  const dQuaternion turned = {std::sqrt(0.5), 0.0, std::sqrt(0.5), 0.0};
  dBodySetQuaternion(a, turned);
  dBodyAddForce(a, 5.0, 6.0, 7.0);
  dBodyAddTorque(a, -1.0, 0.0, 1.0);
  dBodySetPosition(b, -1.0, 0.0, 0.0);
  dBodySetPosition(asleep, 9.0, 9.0, 9.0);
  dBodyDisable(asleep);
  dQuaternion saved_q;
  for (int k = 0; k < 4; ++k) saved_q[k] = dBodyGetQuaternion(a)[k];

  BodySnapshot snapshot;
  const dBodyID bodies[] = {a, nullptr, asleep};  // null and disabled bodies are skipped
  const dBodyID more[] = {b};
  snapshot.save(bodies, more);
  // A step moves a and b and spends the forces; then a is put to sleep and the sleeper moved.
  dWorldStep(world, 0.01);
  ASSERT_NE(dBodyGetPosition(a)[2], 3.0);
  dBodyDisable(a);
  dBodySetPosition(asleep, 0.0, 0.0, 0.0);
  snapshot.restore();

  EXPECT_TRUE(dBodyIsEnabled(a));
  expect_vec(dBodyGetPosition(a), 1.0, 2.0, 3.0);
  expect_vec(dBodyGetLinearVel(a), 0.5, -0.25, 4.0);
  expect_vec(dBodyGetAngularVel(a), 2.0, 0.0, -2.0);
  expect_vec(dBodyGetForce(a), 5.0, 6.0, 7.0);
  expect_vec(dBodyGetTorque(a), -1.0, 0.0, 1.0);
  // Set again, the saved quaternion is normalised once more: the same to an ulp or two.
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(dBodyGetQuaternion(a)[k], saved_q[k], 1e-15) << k;
  expect_vec(dBodyGetPosition(b), -1.0, 0.0, 0.0);
  expect_vec(dBodyGetLinearVel(b), 0.0, 0.0, 0.0);
  EXPECT_FALSE(dBodyIsEnabled(asleep));
  expect_vec(dBodyGetPosition(asleep), 0.0, 0.0, 0.0);

  dWorldDestroy(world);
  dCloseODE();
}

}  // namespace
}  // namespace fragsim
