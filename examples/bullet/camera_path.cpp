#include "camera_path.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

const char* camera_move_name(CameraMove move) {
  switch (move) {
    case CameraMove::walk_in:
      return "walk-in";
    case CameraMove::strafe:
      return "strafe";
    case CameraMove::back_off:
      return "back-off";
    case CameraMove::pan:
      return "pan";
  }
  return "?";
}

CameraPose CameraPath::at(double t_s) const {
  CameraPose pose;
  pose.eye_m = start_m + walk_mps * t_s +
               weave_axis * (weave_m * std::sin(weave_radps * t_s + weave_phase_rad));
  const double yaw = yaw_rad * std::sin(yaw_radps * t_s);  // positive: turned to the left
  pose.forward = {-std::sin(yaw), 0, -std::cos(yaw)};
  pose.right = {std::cos(yaw), 0, -std::sin(yaw)};
  pose.up = {0, 1, 0};
  return pose;
}

CameraPath make_camera_path(CameraMove move, SeededDraws& draws) {
  CameraPath path;
  path.move = move;
  path.start_m = {draws.uniform(-0.3, 0.3), draws.uniform(1.5, 1.7), 0};
  switch (move) {
    case CameraMove::walk_in:  // toward the blast, as in fragsim's front.ini
      path.walk_mps = {0, 0, -draws.uniform(1.0, 2.5)};
      break;
    case CameraMove::strafe: {  // sideways weave while edging forward
      path.walk_mps = {draws.uniform(-0.5, 0.5), 0, -draws.uniform(0.3, 1.2)};
      path.weave_m = draws.uniform(0.2, 0.5);
      path.weave_phase_rad = draws.uniform(0, 2 * std::numbers::pi);
      // Speed at most |walk| + weave w, acceleration at most weave w^2: both kept under the bound.
      const double speed_left_mps = 0.95 * CameraBounds::max_speed_mps - length(path.walk_mps);
      path.weave_radps = std::min({draws.uniform(2.0, 4.0), speed_left_mps / path.weave_m,
                                   std::sqrt(0.95 * CameraBounds::max_accel_mps2 / path.weave_m)});
      break;
    }
    case CameraMove::back_off:  // retreating from the blast
      path.walk_mps = {draws.uniform(-0.3, 0.3), 0, draws.uniform(0.5, 1.5)};
      break;
    case CameraMove::pan:  // looking around while walking slowly
      path.walk_mps = {0, 0, -draws.uniform(0.0, 1.0)};
      path.yaw_rad = draws.uniform(0.15, 0.35);
      // Turn rate at most yaw w, under the declared bound.
      path.yaw_radps =
          std::min(draws.uniform(1.0, 3.0), 0.95 * CameraBounds::max_turn_radps / path.yaw_rad);
      break;
  }
  return path;
}
