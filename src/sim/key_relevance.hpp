#pragma once
// Keys that a scene's own choices make moot, such as a track file when the camera flies its path,
// or the cube's size when the pieces come from a mesh. A key the user set that does nothing is
// almost always a mistake (the mode was forgotten), so loading a scene warns about it
// (scene_file.hpp). The strategies' keys are not among them, as every command may run any strategy
// (compare runs them all, play switches between them), so none is moot by the scene.

#include <optional>
#include <string>

#include "sim/scene.hpp"

namespace fragsim {

// Why `key` ("camera.track_file") has no effect on `scene` as set, as one clause naming the key
// that decides ("only camera.mode = track reads a track file, and camera.mode = path"), or nothing
// when it may have one.
std::optional<std::string> why_no_effect(const Scene& scene, const std::string& key);

}  // namespace fragsim
