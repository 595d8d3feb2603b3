#pragma once

#include <ode/ode.h>

#include <array>
#include <span>
#include <vector>

namespace fragsim {

// The state of a set of ODE bodies, to take a step again from where it began (World::step redoes an
// exact step whose LCP failed), as position, orientation, velocities and the forces and torques
// added for the step. Disabled bodies are left out, as a step does not move them.
class BodySnapshot {
 public:
  void save(std::span<const dBodyID> bodies, std::span<const dBodyID> more);
  // Puts every saved body back, enabling those ODE's auto-disable turned off in the step.
  void restore() const;

 private:
  struct Saved {
    dBodyID body;
    std::array<dReal, 3> position, linear_vel, angular_vel, force, torque;
    std::array<dReal, 4> quaternion;
  };
  void save_one(dBodyID b);
  std::vector<Saved> saved_;
};

}  // namespace fragsim
