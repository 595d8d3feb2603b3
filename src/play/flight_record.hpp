#pragma once
// What a flight leaves behind is the camera track as camera.csv's columns and, beside it, the
// resolved scene that replays it (camera.mode = track, the blast aimed at the camera's start, the
// seed, as many steps as were flown), so `fragsim compare --scene FILE.ini` runs every strategy
// on exactly that flight. Both files are written whole or not at all.

#include <optional>
#include <string>
#include <vector>

#include "control/geometry/camera_pose.hpp"
#include "sim/scene.hpp"

namespace fragsim {

// camera.csv's header and rows (strategy, step, t_s, eye, forward, up, near_m, fovy_deg,
// aspect), numbers in their shortest round-trip form so the track reads back bit for bit.
std::string track_csv(const CameraDef& camera, const std::string& strategy,
                      const std::vector<CameraSample>& samples);

// The scene that replays a flight of `steps` steps of `flight` whose track is the file
// `track_path` (made absolute, so the scene replays from any folder).
Scene replay_scene(const Scene& flight, const std::string& track_path, int steps);

struct RecordPaths {
  std::string track_csv;
  std::string scene_ini;  // the track's path with .ini for its extension
};

// Where flight number `flight` (from 1) of a session is written. With `requested` (--record
// FILE), FILE for the first, FILE's stem with -2, -3, ... for the later ones. Without it,
// play-NNN.csv in `folder` with the smallest NNN for which neither file exists, never over an
// earlier recording.
RecordPaths record_paths(const std::string& requested, int flight, const std::string& folder);

// Whether the first flight's files (record_paths(requested, 1, folder)) can be written, found
// before anyone flies. Neither may be a folder, and each one's temporary file (the AtomicFile
// write_flight uses) is created and removed again. Returns nothing if they can, else why, naming
// the path. Later flights go to the same folder.
std::optional<std::string> record_path_problem(const std::string& requested,
                                               const std::string& folder);

// Writes both files (each through an AtomicFile); throws std::runtime_error naming a path.
void write_flight(const RecordPaths& paths, const Scene& flight, const std::string& strategy,
                  const std::vector<CameraSample>& samples, int steps);

}  // namespace fragsim
