#pragma once
// The camera a person flies, what the keys and the mouse hold turned into one pose per physics
// step. The speed follows the held direction at up to the scene's player acceleration and never
// exceeds V_c (camera.max_speed_mps), the bound strategies are told; keys turn at the scene's turn
// rate, the mouse as far as it moved.

#include <Eigen/Core>

#include "control/geometry/camera_pose.hpp"
#include "sim/scene.hpp"

namespace fragsim {

// What is held at one instant. Axes in [-1, 1]; the mouse's turn is what it moved since the last
// step, consumed by that step.
struct HeldControls {
  double forward = 0.0;  // W / up arrow +1, S / down arrow -1, along the view direction
  double right = 0.0;    // D / right arrow +1, A / left arrow -1
  double yaw = 0.0;      // E +1 turns right, Q -1 left
  double pitch = 0.0;    // R +1 looks up, F -1 down
  double mouse_yaw_rad = 0.0;
  double mouse_pitch_rad = 0.0;
};

class FlightControls {
 public:
  // Starts at `start`, standing still.
  FlightControls(const CameraDef& camera, const CameraPose& start);

  // Advances one step of dt_s under `held` (its mouse turn is consumed, set to 0) and returns the
  // pose at the step's end, stamped t_s.
  CameraSample step(HeldControls& held, double t_s, double dt_s);
  // The present pose, stamped t_s.
  CameraSample sample(double t_s) const;
  const Eigen::Vector3d& velocity_mps() const { return velocity_mps_; }

 private:
  Eigen::Vector3d forward() const;
  Eigen::Vector3d right() const;

  Eigen::Vector3d eye_m_;
  Eigen::Vector3d velocity_mps_ = Eigen::Vector3d::Zero();
  double yaw_rad_ = 0.0;    // 0 looks down -z, positive turns right
  double pitch_rad_ = 0.0;  // positive looks up; kept within +-85 degrees
  double max_speed_mps_;
  double accel_mps2_;  // at +infinity the velocity follows the keys at once
  double turn_radps_;
};

}  // namespace fragsim
