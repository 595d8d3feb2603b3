#pragma once
// A camera track from a CSV file (camera.mode = track) in camera.csv's own columns, so any earlier
// run's camera, or one exported from a game engine, replays. Checked as carefully as a scene file,
// with every problem one line naming file:line.

#include <optional>
#include <string>
#include <vector>

#include "control/geometry/camera_pose.hpp"
#include "geometry/axis_convention.hpp"
#include "sim/scene.hpp"

namespace fragsim {

// How a track file is read: which rows, the speed bound, its clock and its frame.
struct CameraTrackReading {
  std::string strategy;  // the rows of this `strategy` column value (empty means the first row's)
  double max_speed_mps = 0.0;
  TrackTime time = TrackTime::kAsRecorded;
  AxisConvention frame;  // the file's unit and axes; samples come out in fragsim's
};

// The reading a scene's camera asks for (camera.track_strategy, max_speed_mps, track_time,
// track_unit_m, track_up, track_handedness).
CameraTrackReading track_reading(const CameraDef& camera);

// Columns t_s, eye_x_m, eye_y_m, eye_z_m, forward_x, forward_y, forward_z, up_x, up_y, up_z in any
// order after a header row (names may be double-quoted); others are ignored. With a `strategy`
// column, only the rows of `reading.strategy` are taken (empty for the strategy of the first row).
// Each row is turned into fragsim's frame and metres (reading.frame) and, with
// TrackTime::kFromFirstSample, shifted so the first sample taken is at t = 0; the checks below
// apply to the result. Rejected, with file:line: a missing column (the message shows the header
// read and the one expected), a value that is not a finite number, time not strictly increasing, a
// forward/up basis not orthonormal to 1e-6, and a speed between two samples above `max_speed_mps`
// (V_c is what the strategies rely on; the message names the time and the speed). Throws
// InputError.
std::vector<CameraSample> parse_camera_track(const std::string& text, const std::string& origin,
                                             const CameraTrackReading& reading);
std::vector<CameraSample> parse_camera_track(const std::string& text, const std::string& origin,
                                             const std::string& strategy, double max_speed_mps);

// The same from the file at `path` (read through read_text_file).
std::vector<CameraSample> load_camera_track(const std::string& path,
                                            const CameraTrackReading& reading);
std::vector<CameraSample> load_camera_track(const std::string& path, const std::string& strategy,
                                            double max_speed_mps);

// A run asks for the camera at times 0 to `run_end_s`, and a track that does not reach over all of
// them leaves the camera standing still where it does not (sampled_camera.hpp). Nothing when the
// samples cover the run, else one line (without a "warning: " prefix) saying what the track covers,
// what the run needs, and, when a track read as recorded would cover more of the run shifted to
// start at t = 0, that camera.track_time = from_first_sample does that. `name` names the track (its
// file).
std::optional<std::string> track_coverage_warning(const std::vector<CameraSample>& samples,
                                                  double run_end_s, TrackTime time,
                                                  const std::string& name);

// The same for a scene, checking a camera.mode = track scene's samples against its run
// (step_count() * dt_s); nothing for the other modes.
std::optional<std::string> track_coverage_warning(const Scene& scene);

}  // namespace fragsim
