#pragma once

#include <ode/ode.h>

#include <Eigen/Core>
#include <span>

namespace fragsim {

// A speculative ground contact for convex pieces. ODE's convex-plane collider answers only a piece
// that straddles the plane, so a piece falling farther than its own height in one step would pass
// wholly below it unseen and fall for ever (boxes do not, as ODE's box-plane collider keeps every
// corner below the plane). Before such a step the piece gets one contact at its centre of mass,
// allowed to approach the plane by no more than the lowest corner's gap in the step (ODE's surface
// velocity along the normal, dContactMotionN = -gap / dt). The piece ends the step on the plane,
// and ODE's own contacts take over from there, as with Box2D's and Jolt's speculative contacts. A
// piece that already straddles the plane gets the same contact when the step would carry its centre
// past the plane, as ODE's contacts hold its corners, and a piece struck on a corner turns about it
// with most of its centre's speed; its centre comes down to the plane, no farther.
struct GroundSweepDef {
  double height_m = 0.0;  // the plane y = height_m, normal +y
  double gravity_y_mps2 = 0.0;
  double friction = 0.0;
  double cfm_share = 0.0;  // CFM = cfm_share x dt / mass
};

// The piece's corners (body frame, about the centre of mass), bounding radius and mass.
struct GroundSweepPiece {
  dBodyID body = nullptr;
  dGeomID geom = nullptr;
  std::span<const Eigen::Vector3d> vertices_m;
  double radius_m = 0.0;
  double mass_kg = 0.0;
};

// Adds the piece's speculative contact to group, before the step of dt_s and after its forces,
// if the step would carry its centre down by more than half its height above the plane (a
// shallower landing is left to ODE's contacts, as a box's is), or, straddling, past the plane.
// Returns how many it added (0, 1).
int add_ground_sweep_contacts(dWorldID world, dJointGroupID group, dGeomID plane,
                              const GroundSweepPiece& piece, double dt_s,
                              const GroundSweepDef& def);

}  // namespace fragsim
