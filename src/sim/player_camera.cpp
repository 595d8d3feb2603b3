#include "sim/player_camera.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "sim/camera_motion.hpp"
#include "sim/explosion.hpp"
#include "sim/random.hpp"

namespace fragsim {
namespace {

// Mixed into the scene's seed so the player's draws never share the explosion's sequence.
constexpr std::uint64_t kPlayerStream = 0x9E3779B97F4A7C15ull;

// Waiting time of a Poisson process with mean `mean_s` (infinite means never).
double next_wait_s(Random& rng, double mean_s) {
  if (std::isinf(mean_s)) return mean_s;
  return -mean_s * std::log(1.0 - rng.uniform());
}

// A new intended velocity: a reversal, a strafe across the view, or any horizontal direction.
Eigen::Vector3d draw_intent(Random& rng, const Eigen::Vector3d& intent,
                            const Eigen::Vector3d& forward, double max_speed_mps) {
  const double kind = rng.uniform();
  const double speed_mps = rng.uniform() < 0.5 ? max_speed_mps : max_speed_mps * rng.uniform();
  Eigen::Vector3d dir = Eigen::Vector3d::Zero();
  const Eigen::Vector3d flat_intent(intent.x(), 0.0, intent.z());
  const Eigen::Vector3d strafe = forward.cross(Eigen::Vector3d::UnitY());
  if (kind < 0.25 && flat_intent.norm() > 1e-9) {
    dir = -flat_intent.normalized();
  } else if (kind < 0.5 && strafe.norm() > 1e-9) {
    dir = (rng.uniform() < 0.5 ? 1.0 : -1.0) * strafe.normalized();
  } else {
    const double angle = 2.0 * kPi * rng.uniform();
    dir = Eigen::Vector3d(std::cos(angle), 0.0, std::sin(angle));
  }
  return speed_mps * dir;
}

// `from` turned toward `to` (both unit) by at most `max_rad`, on the great circle between them.
Eigen::Vector3d turn_toward(const Eigen::Vector3d& from, const Eigen::Vector3d& to,
                            double max_rad) {
  const double angle = std::acos(std::clamp(from.dot(to), -1.0, 1.0));
  if (angle <= max_rad) return to;
  const double s = std::sin(angle);
  if (s < 1e-12) {  // opposite, so turn about world y (or any axis orthogonal to `from`)
    Eigen::Vector3d axis = from.cross(Eigen::Vector3d::UnitY());
    if (axis.norm() < 1e-9) axis = from.cross(Eigen::Vector3d::UnitX());
    axis.normalize();
    return (std::cos(max_rad) * from + std::sin(max_rad) * axis.cross(from)).normalized();
  }
  return ((std::sin(angle - max_rad) * from + std::sin(max_rad) * to) / s).normalized();
}

}  // namespace

std::vector<CameraSample> player_track(const Scene& scene) {
  const CameraDef& cam = scene.camera;
  const double dt = scene.sim.dt_s;
  const auto count =
      static_cast<std::size_t>(scene.step_count()) + static_cast<std::size_t>(std::ceil(2.0 / dt));
  const double accel_step = cam.player_accel_mps2 * dt;  // infinite means instant
  const double turn_step_rad = cam.turn_rate_degps * kPi / 180.0 * dt;
  const Eigen::Vector3d centre = object_centre(scene);

  Random rng(scene.sim.seed ^ kPlayerStream);
  Eigen::Vector3d eye = cam.waypoints_m.front();
  Eigen::Vector3d target = cam.look_at_m.front();
  CameraPose view = pose_looking_at(cam, eye, target);
  Eigen::Vector3d intent =
      draw_intent(rng, Eigen::Vector3d::Zero(), view.forward, cam.max_speed_mps);
  Eigen::Vector3d velocity = intent;  // already moving when the object explodes
  double next_change_s = next_wait_s(rng, cam.player_interval_s);

  std::vector<CameraSample> out;
  out.reserve(count);
  for (std::size_t k = 0; k < count; ++k) {
    const double t = static_cast<double>(k) * dt;
    out.push_back({t, eye, view.forward, view.up});
    while (t >= next_change_s) {
      intent = draw_intent(rng, intent, view.forward, cam.max_speed_mps);
      target = centre + cam.player_look_radius_m * random_in_unit_ball(rng);
      next_change_s += next_wait_s(rng, cam.player_interval_s);
    }
    const Eigen::Vector3d change = intent - velocity;
    const double change_norm = change.norm();
    velocity = change_norm <= accel_step ? intent : velocity + (accel_step / change_norm) * change;

    const Eigen::Vector3d to_target = target - eye;
    if (to_target.norm() > 1e-6) {
      const Eigen::Vector3d forward =
          turn_toward(view.forward, to_target.normalized(), turn_step_rad);
      view = pose_looking_at(cam, eye, eye + forward);
    }
    eye += velocity * dt;
  }
  return out;
}

}  // namespace fragsim
