#pragma once
// The stress suite's observer: after every step it checks that each fragment's state and each
// applied force is finite, that no force exceeds the strategy's acceleration cap, and that no
// fragment has more energy than the explosion, the strategy's forces and the contacts can have
// given it (the energy budget below). It only reads snapshots.
//
// The energy budget, per fragment (translational energy only: a snapshot has no angular
// velocity; the rotational energy the explosion gave is added to the budget, because contacts
// turn spin into translation):
//
//   K(t) = m |v|^2 / 2  <=  B(t) + m g.p(t)      (E = K - m g.p must stay below B)
//   B(0) = K(0) - m g.p(0) + E_rot(0)            (E_rot from explode(): the spawn's spin)
//   each step, + |F| ((|v_k| + |v_k+1|) / 2 + |g| dt / 2) dt  for the strategy's force F:
//     the exact energy change of ODE's semi-implicit Euler step in free flight is
//     F.(v_k + v_k+1) dt / 2 - (g.F) dt^2 / 2 - m |g|^2 dt^2 / 2, which this bounds;
//   at each contact onset (touched now, not in the step before), + the most a contact can
//     inject: the solver makes the separating normal velocity at most max(restitution * incoming,
//     ERP correction), the correction is capped at World's dWorldSetContactMaxCorrectingVel
//     c = 10 m/s, friction only removes; so against a still surface + m c^2 / 2. Against the
//     wall (a kinematic box moving at the camera's speed u), the same in the wall's frame:
//     |v'| <= u + sqrt((|v| + u)^2 + c^2), so + m/2 ((u + sqrt((v + u)^2 + c^2))^2 - v^2), with
//     v the largest speed the fragment can bring into the step;
//   while in contact, + m |g| (growth of the deepest ground penetration in this contact): the
//     correction lifts a deeply sunk fragment back at up to c, regaining that potential energy;
//   wall runs, each step in contact, + m |g| u dt: the wall may carry the fragment upward (u: a
//     path camera's speed_mps, a player's or a track's V_c, the most either moves at);
//   fragment collisions on, at each onset, + m |g| 4 r: two overlapping fragments (overlap at
//     most their size) are pushed apart, lifting one by up to that.
// With fragment collisions on, fragments trade energy (a fast one hits a slow one), so the bound
// is checked on the sum over fragments, not per fragment. A rounding slack of 1e-9 of the terms'
// size (plus 1e-12 J) is allowed.

#include <limits>
#include <string>
#include <vector>

#include "sim/run_observer.hpp"
#include "sim/scene.hpp"

namespace fragsim::stress {

// ODE's contact settings in src/sim/world.cpp that the energy budget relies on.
inline constexpr double kMaxCorrectingVelMps = 10.0;  // dWorldSetContactMaxCorrectingVel

// What one run did, as far as the checks go.
struct RunHealth {
  std::string strategy;
  int fragments = 0;
  int steps = 0;
  bool energy_per_fragment = true;  // false with fragment collisions on: checked on the sum

  long nonfinite_states = 0;   // snapshot fragment states with a NaN or infinity
  long nonfinite_forces = 0;   // applied forces with a NaN or infinity
  long nonfinite_near = 0;     // snapshot near distances not finite and > 0
  long unexpected_forces = 0;  // forces from a strategy that applies none
  long forces_over_cap = 0;    // |F| > m a_cap (1 + 1e-9)
  long energy_violations = 0;  // fragment-steps (or steps, on the sum) over the budget
  long contact_onsets = 0;

  double max_abs_position_m = 0.0;
  double max_speed_mps = 0.0;
  double max_force_N = 0.0;
  double max_accel_mps2 = 0.0;  // |F| / m
  double max_force_over_cap = 0.0;

  // The worst fragment-step: largest K / (B + m g.p), the share of its budget it used.
  double max_energy_ratio = 0.0;
  int energy_fragment = -1;
  int energy_step = -1;
  double energy_K_J = 0.0;        // K there
  double energy_allowed_J = 0.0;  // B + m g.p there
  // The same ratio on the sum over fragments (the checked one with collisions on).
  double max_total_energy_ratio = 0.0;
  int total_energy_step = -1;
  // The largest ratio against the budget without any contact allowance (explosion and forces
  // only): above 1 means contacts did inject energy, and by how much.
  double max_no_contact_ratio = 0.0;
};

class HealthObserver final : public RunObserver {
 public:
  void begin(const RunInfo& info, const StepSnapshot& initial) override;
  void observe(const StepSnapshot& snap) override;

  // One entry per run, in run order.
  const std::vector<RunHealth>& runs() const { return runs_; }

 private:
  struct Fragment {
    double budget_J = 0.0;             // B
    double no_contact_budget_J = 0.0;  // B without contact allowances
    double speed_mps = 0.0;            // |v| at the last snapshot
    double episode_depth_m = 0.0;      // deepest ground penetration in the current contact
    bool touched = false;
  };

  void check_state(const StepSnapshot& snap);
  void check_forces(const StepSnapshot& snap);
  void check_energy(const StepSnapshot& snap);

  std::vector<RunHealth> runs_;
  const Scene* scene_ = nullptr;
  double dt_s_ = 0.0;
  double force_cap_mps2_ = 0.0;  // the strategy's acceleration cap
  bool applies_forces_ = false;
  double wall_speed_mps_ = 0.0;  // u: the wall's largest speed (wall runs), else 0
  std::vector<Fragment> fragments_;
  std::vector<double> force_N_;  // |F| this step, by fragment
};

}  // namespace fragsim::stress
