#include "sim/body_snapshot.hpp"

#include <algorithm>

namespace fragsim {

void BodySnapshot::save(std::span<const dBodyID> bodies, std::span<const dBodyID> more) {
  saved_.clear();
  for (dBodyID b : bodies) save_one(b);
  for (dBodyID b : more) save_one(b);
}

void BodySnapshot::save_one(dBodyID b) {
  if (b == nullptr || !dBodyIsEnabled(b)) return;
  Saved& s = saved_.emplace_back();
  s.body = b;
  auto copy = [](const dReal* from, auto& to) { std::copy_n(from, to.size(), to.begin()); };
  copy(dBodyGetPosition(b), s.position);
  copy(dBodyGetQuaternion(b), s.quaternion);
  copy(dBodyGetLinearVel(b), s.linear_vel);
  copy(dBodyGetAngularVel(b), s.angular_vel);
  copy(dBodyGetForce(b), s.force);
  copy(dBodyGetTorque(b), s.torque);
}

void BodySnapshot::restore() const {
  for (const Saved& s : saved_) {
    if (!dBodyIsEnabled(s.body)) dBodyEnable(s.body);
    dBodySetPosition(s.body, s.position[0], s.position[1], s.position[2]);
    dBodySetQuaternion(s.body, s.quaternion.data());
    dBodySetLinearVel(s.body, s.linear_vel[0], s.linear_vel[1], s.linear_vel[2]);
    dBodySetAngularVel(s.body, s.angular_vel[0], s.angular_vel[1], s.angular_vel[2]);
    dBodySetForce(s.body, s.force[0], s.force[1], s.force[2]);
    dBodySetTorque(s.body, s.torque[0], s.torque[1], s.torque[2]);
  }
}

}  // namespace fragsim
