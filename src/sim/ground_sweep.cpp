#include "sim/ground_sweep.hpp"

#include <algorithm>
#include <cmath>

namespace fragsim {

int add_ground_sweep_contacts(dWorldID world, dJointGroupID group, dGeomID plane,
                              const GroundSweepPiece& piece, double dt_s,
                              const GroundSweepDef& def) {
  // Called for every awake piece every step, so the common answers (far above the ground, resting
  // on it, rising) come first and touch no memory but the body's.
  const dReal* p = dBodyGetPosition(piece.body);
  const dReal* v = dBodyGetLinearVel(piece.body);
  const dReal* f = dBodyGetForce(piece.body);
  double accel_y_mps2 = f[1] / piece.mass_kg;
  if (dBodyGetGravityMode(piece.body) != 0) accel_y_mps2 += def.gravity_y_mps2;
  // How far the step would carry the centre down if nothing stopped it (ODE's semi-implicit Euler
  // moves the piece by the velocity it ends the step with). The spin does not count, as it keeps
  // every corner within the bounding radius of the centre, and whatever it turns below the plane
  // around a centre that stays above leaves the piece straddling, which ODE's collider answers.
  const double descent_m = -(v[1] + accel_y_mps2 * dt_s) * dt_s;
  const double centre_gap_m = p[1] - def.height_m;
  if (descent_m <= 0.0 || centre_gap_m - piece.radius_m > descent_m) return 0;
  if (centre_gap_m + piece.radius_m <= 0.0) return 0;  // wholly below, see below

  const dReal* r = dBodyGetRotation(piece.body);  // 3x4 row-major
  double lowest_m = INFINITY;
  double highest_m = -INFINITY;
  for (const Eigen::Vector3d& b : piece.vertices_m) {
    const double g = centre_gap_m + r[4] * b.x() + r[5] * b.y() + r[6] * b.z();
    lowest_m = std::min(lowest_m, g);
    highest_m = std::max(highest_m, g);
  }
  // One already wholly below came there some other way (a strategy's force through resting
  // contacts) that a sweep cannot undo.
  if (highest_m <= 0.0) return 0;
  // How far the centre may come down in this step. Above the plane it is the lowest corner's gap,
  // so the piece ends the step on it; a landing shallower than half its height is left to ODE's
  // collider, which answers the piece once it straddles. Once it straddles, ODE's corner contacts
  // hold the corners, not the centre. A piece struck on one corner turns about it and keeps most of
  // its centre's speed (a rod struck at its end, three quarters), so a fast one could carry its
  // centre past the plane and end wholly below, out of the corners' reach (3 of 1,000 of the
  // physics benchmark's random hulls at 8 m/s). So its centre may come down to the plane, no
  // farther. A centre already below is held where it is, not pushed back up, as that would be a
  // half-space contact after the fact, which gains energy; ODE's contacts bring it out.
  double allowed_m = lowest_m;
  if (lowest_m > 0.0) {
    if (descent_m <= 0.5 * (lowest_m + highest_m)) return 0;
  } else {
    allowed_m = std::max(centre_gap_m, 0.0);
    if (descent_m <= allowed_m) return 0;
  }

  // One contact at the centre of mass holds the centre's descent in this step to allowed_m, so the
  // centre stays above the plane and the piece is never wholly below, however it turns, and it
  // exerts no torque. Contacts at the corners would constrain the corners' velocities, spin
  // included, and a piece spinning at hundreds of turns a step (the soak's seed 3023, 12,167 cells
  // blown at 170 m/s, dt 0.1 s) would be flung up by corners that never come near the plane.
  dContact c{};
  for (int row = 0; row < 3; ++row) c.geom.pos[row] = p[row];
  c.geom.normal[1] = 1.0;  // from the plane into the piece
  c.geom.depth = 0.0;
  c.geom.g1 = piece.geom;
  c.geom.g2 = plane;
  // No bounce, because ODE measures it against the surface velocity, here the allowed approach. A
  // piece fast enough to need this lands without rebound; one landing slower bounces as usual.
  c.surface.mode = dContactMotionN | dContactApprox1 | dContactSoftCFM;
  c.surface.mu = def.friction;
  c.surface.soft_cfm = def.cfm_share * dt_s / piece.mass_kg;  // keeps that share of the speed
  c.surface.motionN = -allowed_m / dt_s;
  dJointID j = dJointCreateContact(world, group, &c);
  dJointAttach(j, piece.body, nullptr);
  return 1;
}

}  // namespace fragsim
