#pragma once
// A seeded model of a person with a gamepad (camera.mode = player), as timed samples one physics
// step apart. The player starts at the first waypoint looking at the first look-at point. At random
// moments (a Poisson process, mean camera.player_interval_s apart) the intended velocity changes to
// a full reversal, a strafe across the view or a new direction, in the horizontal plane (a walking
// camera keeps its height), at full speed V_c half of the time and otherwise at a uniform share of
// it. At the same moments the view target moves to a random point within
// camera.player_look_radius_m of the object's centre. The actual velocity follows the intended one
// at an acceleration of at most camera.player_accel_mps2 (infinity means at once) and the view
// turns toward the target at up to camera.turn_rate_degps. The same scene and seed give the same
// track; the draws come from their own stream, so the explosion is the same as in every other mode.

#include <vector>

#include "control/geometry/camera_pose.hpp"
#include "sim/scene.hpp"

namespace fragsim {

// Samples at t = k dt for k = 0 .. the run's last step plus two seconds (an aimed blast asks where
// the camera will be when the debris arrives, which may be after the run ends).
std::vector<CameraSample> player_track(const Scene& scene);

}  // namespace fragsim
