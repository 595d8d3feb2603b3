#include "play/flight_controls.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace fragsim {
namespace {

// Looking straight up or down would leave yaw undefined and the view's up vector flipping.
constexpr double kMaxPitchRad = 85.0 * kPi / 180.0;

}  // namespace

FlightControls::FlightControls(const CameraDef& camera, const CameraPose& start)
    : eye_m_(start.eye_m),
      max_speed_mps_(camera.max_speed_mps),
      accel_mps2_(camera.player_accel_mps2),
      turn_radps_(camera.turn_rate_degps * kPi / 180.0) {
  const Eigen::Vector3d f = start.forward.normalized();
  yaw_rad_ = std::atan2(f.x(), -f.z());
  pitch_rad_ = std::clamp(std::asin(std::clamp(f.y(), -1.0, 1.0)), -kMaxPitchRad, kMaxPitchRad);
}

Eigen::Vector3d FlightControls::forward() const {
  const double cp = std::cos(pitch_rad_);
  return Eigen::Vector3d(std::sin(yaw_rad_) * cp, std::sin(pitch_rad_), -std::cos(yaw_rad_) * cp)
      .normalized();
}

Eigen::Vector3d FlightControls::right() const {
  return Eigen::Vector3d(std::cos(yaw_rad_), 0.0, std::sin(yaw_rad_)).normalized();
}

CameraSample FlightControls::sample(double t_s) const {
  CameraSample s;
  s.t_s = t_s;
  s.eye_m = eye_m_;
  s.forward = forward();
  s.up = right().cross(s.forward).normalized();
  return s;
}

CameraSample FlightControls::step(HeldControls& held, double t_s, double dt_s) {
  yaw_rad_ += std::clamp(held.yaw, -1.0, 1.0) * turn_radps_ * dt_s + held.mouse_yaw_rad;
  yaw_rad_ = std::remainder(yaw_rad_, 2.0 * kPi);
  pitch_rad_ += std::clamp(held.pitch, -1.0, 1.0) * turn_radps_ * dt_s + held.mouse_pitch_rad;
  pitch_rad_ = std::clamp(pitch_rad_, -kMaxPitchRad, kMaxPitchRad);
  held.mouse_yaw_rad = 0.0;
  held.mouse_pitch_rad = 0.0;

  Eigen::Vector3d wish =
      std::clamp(held.forward, -1.0, 1.0) * forward() + std::clamp(held.right, -1.0, 1.0) * right();
  if (wish.norm() > 1.0) wish.normalize();  // diagonal keys are no faster
  const Eigen::Vector3d target = max_speed_mps_ * wish;
  Eigen::Vector3d dv = target - velocity_mps_;
  const double max_dv = accel_mps2_ * dt_s;  // infinite for instant turns
  if (dv.norm() > max_dv) dv *= max_dv / dv.norm();
  velocity_mps_ += dv;
  // Rounding must never lift the speed over V_c, as the replayed track is checked against it.
  if (velocity_mps_.norm() > max_speed_mps_) velocity_mps_ *= max_speed_mps_ / velocity_mps_.norm();
  eye_m_ += velocity_mps_ * dt_s;
  return sample(t_s);
}

}  // namespace fragsim
