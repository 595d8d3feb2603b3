#include "sim/ground_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numeric>
#include <vector>

namespace fragsim {

int add_ground_sweep_contacts(dWorldID world, dJointGroupID group, dGeomID plane,
                              const GroundSweepPiece& piece, double dt_s,
                              const GroundSweepDef& def) {
  const dReal* p = dBodyGetPosition(piece.body);
  const dReal* v = dBodyGetLinearVel(piece.body);
  const dReal* w = dBodyGetAngularVel(piece.body);
  const dReal* f = dBodyGetForce(piece.body);
  dMass mass;
  dBodyGetMass(piece.body, &mass);
  double accel_y_mps2 = f[1] / mass.mass;
  if (dBodyGetGravityMode(piece.body) != 0) {
    dVector3 g;
    dWorldGetGravity(world, g);
    accel_y_mps2 += g[1];
  }
  // The fall speed the step would end with if nothing stopped it (ODE's semi-implicit Euler moves
  // the piece by that velocity times dt), plus what the spin can add at any corner.
  const double fall_mps = std::max(0.0, -(v[1] + accel_y_mps2 * dt_s));
  const double spin_radps = std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  const double approach_m = (fall_mps + spin_radps * piece.radius_m) * dt_s;
  const double centre_gap_m = p[1] - def.height_m;
  if (centre_gap_m - piece.radius_m > approach_m) return 0;  // out of reach this step

  const dReal* r = dBodyGetRotation(piece.body);  // 3x4 row-major
  const std::size_t n = piece.vertices_m.size();
  std::vector<double> gap_m(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector3d& b = piece.vertices_m[i];
    gap_m[i] = centre_gap_m + r[4] * b.x() + r[5] * b.y() + r[6] * b.z();
  }
  const auto [lowest, highest] = std::minmax_element(gap_m.begin(), gap_m.end());
  // Straddling or below: ODE's collider answers a straddling piece, and one already wholly below
  // came there some other way (a strategy's force through resting contacts) that a sweep cannot
  // undo.
  if (*lowest <= 0.0) return 0;
  if (approach_m <= 0.5 * (*lowest + *highest)) return 0;

  const double soft_cfm = def.cfm_share * dt_s / mass.mass;  // as the ground's own contacts
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return gap_m[a] < gap_m[b]; });
  int added = 0;
  for (std::size_t k = 0; k < n && added < def.max_contacts; ++k) {
    const std::size_t i = order[k];
    if (gap_m[i] >= approach_m) break;  // this corner and the higher ones cannot reach
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
    c.surface.motionN = -gap_m[i] / dt_s;
    dJointID j = dJointCreateContact(world, group, &c);
    dJointAttach(j, piece.body, nullptr);
    ++added;
  }
  return added;
}

}  // namespace fragsim
