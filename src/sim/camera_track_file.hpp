#pragma once
// A camera track from a CSV file (camera.mode = track): camera.csv's own columns, so any earlier
// run's camera, or one exported from a game engine, replays. Checked as carefully as a scene file:
// every problem is one line naming file:line.

#include <string>
#include <vector>

#include "geometry/camera_pose.hpp"

namespace fragsim {

// Columns t_s, eye_x_m, eye_y_m, eye_z_m, forward_x, forward_y, forward_z, up_x, up_y, up_z in
// any order after a header row; others are ignored. With a `strategy` column, only the rows of
// `strategy` are taken (empty: the strategy of the first row). Rejected, with file:line: a missing
// column, a value that is not a finite number, time not strictly increasing, a forward/up basis not
// orthonormal to 1e-6, and a speed between two samples above `max_speed_mps` (V_c is what the
// strategies rely on; the message names the time and the speed). Throws InputError.
std::vector<CameraSample> parse_camera_track(const std::string& text, const std::string& origin,
                                             const std::string& strategy, double max_speed_mps);

// The same from the file at `path` (read through read_input_file).
std::vector<CameraSample> load_camera_track(const std::string& path, const std::string& strategy,
                                            double max_speed_mps);

}  // namespace fragsim
