#include "health_observer.hpp"

#include <algorithm>
#include <cmath>

#include "sim/explosion.hpp"

namespace fragsim::stress {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Rotational energy of a box spinning at w about its centre (body axes = world axes at spawn).
double rotational_energy_J(const FragmentSpawn& s) {
  const Eigen::Vector3d size = 2.0 * s.half_extents_m;
  const Eigen::Vector3d sq = size.cwiseProduct(size);
  const Eigen::Vector3d inertia =
      s.mass_kg / 12.0 * Eigen::Vector3d(sq.y() + sq.z(), sq.x() + sq.z(), sq.x() + sq.y());
  return 0.5 * inertia.dot(s.angular_velocity_radps.cwiseProduct(s.angular_velocity_radps));
}

// Height of the box's lowest corner.
double lowest_y(const FragmentState& f) {
  const Eigen::Matrix3d& r = f.rotation;
  const Eigen::Vector3d& h = f.half_extents_m;
  return f.position_m.y() -
         (std::abs(r(1, 0)) * h.x() + std::abs(r(1, 1)) * h.y() + std::abs(r(1, 2)) * h.z());
}

// K / (allowed + slack): the share of its budget a fragment (or all of them) used.
double used_share(double kinetic_J, double allowed_J, double slack_J) {
  const double denom = allowed_J + slack_J;
  if (denom <= 0.0) return kinetic_J > 0.0 ? kInf : 0.0;
  return kinetic_J / denom;
}

}  // namespace

void HealthObserver::begin(const RunInfo& info, const StepSnapshot& initial) {
  scene_ = info.scene;
  dt_s_ = info.dt_s;
  RunHealth h;
  h.strategy = info.strategy;
  h.fragments = info.fragment_count;
  h.steps = info.step_count;
  h.energy_per_fragment = !scene_->sim.fragment_collisions;
  runs_.push_back(h);

  applies_forces_ = true;
  if (info.strategy == "edge") {
    force_cap_mps2_ = scene_->strategies.edge.a_max_mps2;
  } else if (info.strategy == "edge-min") {
    force_cap_mps2_ = scene_->strategies.edge_min.a_max_mps2;
  } else if (info.strategy == "deflect-all") {
    force_cap_mps2_ = scene_->strategies.deflect_all.accel_mps2;
  } else {
    force_cap_mps2_ = 0.0;
    applies_forces_ = false;
  }
  // The wall rides with the camera: a path camera moves at speed_mps, a player or a track at up
  // to V_c (speed_mps is not theirs).
  const CameraDef& cam = scene_->camera;
  wall_speed_mps_ = info.strategy != "wall"         ? 0.0
                    : cam.mode == CameraMode::kPath ? cam.speed_mps
                                                    : std::max(cam.speed_mps, cam.max_speed_mps);

  const std::vector<FragmentSpawn> spawns = explode(*scene_);
  const Eigen::Vector3d& g = scene_->sim.gravity_mps2;
  fragments_.assign(initial.fragments.size(), Fragment{});
  force_N_.assign(initial.fragments.size(), 0.0);
  for (std::size_t i = 0; i < initial.fragments.size(); ++i) {
    const FragmentState& f = initial.fragments[i];
    const double m = f.mass_kg;
    Fragment& e = fragments_[i];
    e.budget_J = 0.5 * m * f.velocity_mps.squaredNorm() - m * g.dot(f.position_m) +
                 (i < spawns.size() ? rotational_energy_J(spawns[i]) : 0.0);
    e.no_contact_budget_J = e.budget_J;
    e.speed_mps = f.velocity_mps.norm();
    e.touched = f.touched;
  }
  check_state(initial);
}

void HealthObserver::observe(const StepSnapshot& snap) {
  check_state(snap);
  check_forces(snap);
  check_energy(snap);
  for (const AppliedForce& f : snap.forces) force_N_[static_cast<std::size_t>(f.fragment)] = 0.0;
}

void HealthObserver::check_state(const StepSnapshot& snap) {
  RunHealth& h = runs_.back();
  for (const FragmentState& f : snap.fragments) {
    if (!f.position_m.allFinite() || !f.velocity_mps.allFinite() || !f.rotation.allFinite()) {
      ++h.nonfinite_states;
      continue;
    }
    h.max_abs_position_m = std::max(h.max_abs_position_m, f.position_m.cwiseAbs().maxCoeff());
    h.max_speed_mps = std::max(h.max_speed_mps, f.velocity_mps.norm());
  }
  if (!std::isfinite(snap.camera.near_m) || !(snap.camera.near_m > 0.0)) ++h.nonfinite_near;
}

void HealthObserver::check_forces(const StepSnapshot& snap) {
  RunHealth& h = runs_.back();
  for (const AppliedForce& af : snap.forces) {
    if (!applies_forces_) ++h.unexpected_forces;
    if (!af.force_N.allFinite()) {
      ++h.nonfinite_forces;
      continue;
    }
    const auto i = static_cast<std::size_t>(af.fragment);
    const double m = snap.fragments[i].mass_kg;
    const double norm_N = af.force_N.norm();
    force_N_[i] = norm_N;
    h.max_force_N = std::max(h.max_force_N, norm_N);
    h.max_accel_mps2 = std::max(h.max_accel_mps2, norm_N / m);
    const double cap_N = m * force_cap_mps2_;
    const double over = cap_N > 0.0 ? norm_N / cap_N : (norm_N > 0.0 ? kInf : 0.0);
    h.max_force_over_cap = std::max(h.max_force_over_cap, over);
    if (over > 1.0 + 1e-9) ++h.forces_over_cap;
  }
}

void HealthObserver::check_energy(const StepSnapshot& snap) {
  RunHealth& h = runs_.back();
  const Eigen::Vector3d& g = scene_->sim.gravity_mps2;
  const double g_mps2 = g.norm();
  const double dt = dt_s_;
  const double c = kMaxCorrectingVelMps;
  const double u = wall_speed_mps_;
  const bool ground = scene_->ground.enabled;
  const double ground_m = scene_->ground.height_m;
  const bool collisions = scene_->sim.fragment_collisions;

  double total_K = 0.0;
  double total_allowed = 0.0;
  double total_slack = 0.0;
  for (std::size_t i = 0; i < snap.fragments.size(); ++i) {
    const FragmentState& f = snap.fragments[i];
    Fragment& e = fragments_[i];
    const double m = f.mass_kg;
    const double speed = f.velocity_mps.norm();
    const double force_N = force_N_[i];
    const double work_J = force_N * (0.5 * (e.speed_mps + speed) + 0.5 * g_mps2 * dt) * dt;
    e.budget_J += work_J;
    e.no_contact_budget_J += work_J;
    if (f.touched) {
      if (!e.touched) {
        ++h.contact_onsets;
        // The fastest it can arrive at the contact: its last speed plus a step of gravity and
        // force.
        const double v_in = e.speed_mps + (g_mps2 + force_N / m) * dt;
        const double out = u + std::sqrt((v_in + u) * (v_in + u) + c * c);
        e.budget_J += 0.5 * m * (out * out - v_in * v_in);
        if (collisions) e.budget_J += m * g_mps2 * 4.0 * f.radius_m;
      }
      if (ground) {
        const double depth = std::max(ground_m - lowest_y(f), 0.0);
        if (depth > e.episode_depth_m) {
          e.budget_J += m * g_mps2 * (depth - e.episode_depth_m);
          e.episode_depth_m = depth;
        }
      }
      e.budget_J += m * g_mps2 * u * dt;
    } else {
      e.episode_depth_m = 0.0;
    }
    e.touched = f.touched;
    e.speed_mps = speed;

    const double K = 0.5 * m * speed * speed;
    const double potential = m * g.dot(f.position_m);  // -PE
    const double allowed = e.budget_J + potential;
    const double slack = 1e-9 * (std::abs(e.budget_J) + std::abs(potential) + K) + 1e-12;
    const double share = used_share(K, allowed, slack);
    if (share > h.max_energy_ratio || h.energy_fragment < 0) {
      h.max_energy_ratio = share;
      h.energy_fragment = static_cast<int>(i);
      h.energy_step = snap.step;
      h.energy_K_J = K;
      h.energy_allowed_J = allowed;
    }
    h.max_no_contact_ratio =
        std::max(h.max_no_contact_ratio, used_share(K, e.no_contact_budget_J + potential, slack));
    if (h.energy_per_fragment && share > 1.0) ++h.energy_violations;
    total_K += K;
    total_allowed += allowed;
    total_slack += slack;
  }
  const double total_share = used_share(total_K, total_allowed, total_slack);
  if (total_share > h.max_total_energy_ratio || h.total_energy_step < 0) {
    h.max_total_energy_ratio = total_share;
    h.total_energy_step = snap.step;
  }
  if (!h.energy_per_fragment && total_share > 1.0) ++h.energy_violations;
}

}  // namespace fragsim::stress
