// The player's camera: a path that is a function of time, so the physics can ask for the pose at
// any substep's start (not only at rendered frames), and that keeps the bounds it declares.
#pragma once

#include <numbers>

#include "seeded_draws.hpp"
#include "vec3.hpp"

enum class CameraMove { walk_in, strafe, back_off, pan };

const char* camera_move_name(CameraMove move);

// What the game declares to the controller, and what every path below keeps. The paths turn in
// radians; the controller takes every angle in degrees.
struct CameraBounds {
  static constexpr double max_speed_mps = 3.0;
  static constexpr double max_accel_mps2 = 6.0;
  static constexpr double max_turn_radps = 1.0;
  static constexpr double max_turn_degps = max_turn_radps * 180.0 / std::numbers::pi;
};

struct CameraPose {
  Vec3 eye_m;
  Vec3 right, up, forward;  // orthonormal; forward is the view axis
};

// eye(t) = start + walk t + weave sin(weave_radps t + phase) along weave_axis; the view turns
// about the vertical by yaw_rad sin(yaw_radps t) from looking down -z.
struct CameraPath {
  CameraMove move = CameraMove::walk_in;
  Vec3 start_m;
  Vec3 walk_mps;
  Vec3 weave_axis{1, 0, 0};
  double weave_m = 0, weave_radps = 0, weave_phase_rad = 0;
  double yaw_rad = 0, yaw_radps = 0;

  CameraPose at(double t_s) const;
};

// A path of the given kind with seeded speeds, amplitudes and phases, within CameraBounds.
CameraPath make_camera_path(CameraMove move, SeededDraws& draws);
