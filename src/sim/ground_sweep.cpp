#include "sim/ground_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace fragsim {

int add_ground_sweep_contacts(dWorldID world, dJointGroupID group, dGeomID plane,
                              const GroundSweepPiece& piece, double dt_s,
                              const GroundSweepDef& def) {
  // Called for every awake piece every step: the common answers (far above the ground, resting on
  // it) come first and touch no memory but the body's.
  const dReal* p = dBodyGetPosition(piece.body);
  const dReal* v = dBodyGetLinearVel(piece.body);
  const dReal* w = dBodyGetAngularVel(piece.body);
  const dReal* f = dBodyGetForce(piece.body);
  double accel_y_mps2 = f[1] / piece.mass_kg;
  if (dBodyGetGravityMode(piece.body) != 0) accel_y_mps2 += def.gravity_y_mps2;
  // The fall speed the step would end with if nothing stopped it (ODE's semi-implicit Euler moves
  // the piece by that velocity times dt), plus what the spin can add at any corner.
  const double fall_mps = std::max(0.0, -(v[1] + accel_y_mps2 * dt_s));
  const double spin_radps = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  const double approach_m = (fall_mps + spin_radps * piece.radius_m) * dt_s;
  const double centre_gap_m = p[1] - def.height_m;
  if (centre_gap_m - piece.radius_m > approach_m) return 0;  // out of reach this step
  if (centre_gap_m + piece.radius_m <= 0.0) return 0;        // wholly below: see below

  const dReal* r = dBodyGetRotation(piece.body);  // 3x4 row-major
  auto gap_of = [&](const Eigen::Vector3d& b) {
    return centre_gap_m + r[4] * b.x() + r[5] * b.y() + r[6] * b.z();
  };
  double lowest_m = INFINITY;
  double highest_m = -INFINITY;
  for (const Eigen::Vector3d& b : piece.vertices_m) {
    const double g = gap_of(b);
    lowest_m = std::min(lowest_m, g);
    highest_m = std::max(highest_m, g);
  }
  // Straddling or below: ODE's collider answers a straddling piece, and one already wholly below
  // came there some other way (a strategy's force through resting contacts) that a sweep cannot
  // undo.
  if (lowest_m <= 0.0) return 0;
  if (approach_m <= 0.5 * (lowest_m + highest_m)) return 0;

  // The corners that can reach the plane, lowest first (ties in vertex order).
  std::vector<std::pair<double, std::size_t>> reach;
  for (std::size_t i = 0; i < piece.vertices_m.size(); ++i) {
    const double g = gap_of(piece.vertices_m[i]);
    if (g < approach_m) reach.emplace_back(g, i);
  }
  std::sort(reach.begin(), reach.end());
  const double soft_cfm = def.cfm_share * dt_s / piece.mass_kg;  // as the ground's own contacts
  int added = 0;
  for (const auto& [gap_m, i] : reach) {
    if (added == def.max_contacts) break;
    const Eigen::Vector3d& b = piece.vertices_m[i];
    dContact c{};
    for (int row = 0; row < 3; ++row) {
      c.geom.pos[row] =
          p[row] + r[row * 4] * b.x() + r[row * 4 + 1] * b.y() + r[row * 4 + 2] * b.z();
    }
    c.geom.normal[1] = 1.0;  // from the plane into the piece
    c.geom.depth = 0.0;
    c.geom.g1 = piece.geom;
    c.geom.g2 = plane;
    // No bounce: ODE measures it against the surface velocity, here the allowed approach. A
    // piece fast enough to need these lands without rebound; one landing slower bounces as before.
    c.surface.mode = dContactMotionN | dContactApprox1 | dContactSoftCFM;
    c.surface.mu = def.friction;
    c.surface.soft_cfm = soft_cfm;
    c.surface.motionN = -gap_m / dt_s;
    dJointID j = dJointCreateContact(world, group, &c);
    dJointAttach(j, piece.body, nullptr);
    ++added;
  }
  return added;
}

}  // namespace fragsim
