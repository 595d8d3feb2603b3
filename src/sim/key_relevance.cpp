#include "sim/key_relevance.hpp"

#include <functional>
#include <vector>

namespace fragsim {
namespace {

struct Rule {
  std::vector<std::string> keys;
  std::function<std::optional<std::string>(const Scene&)> moot;  // why, when the keys are moot
};

std::string mode_name(CameraMode m) {
  switch (m) {
    case CameraMode::kPath:
      return "path";
    case CameraMode::kTrack:
      return "track";
    case CameraMode::kPlayer:
      return "player";
  }
  return "";
}

const std::vector<Rule>& rules() {
  static const std::vector<Rule> table{
      {{"camera.track_file", "camera.track_strategy", "camera.track_time", "camera.track_unit_m",
        "camera.track_up", "camera.track_handedness"},
       [](const Scene& s) -> std::optional<std::string> {
         if (s.camera.mode == CameraMode::kTrack) return std::nullopt;
         return "only camera.mode = track reads a track, and camera.mode = " +
                mode_name(s.camera.mode);
       }},
      {{"camera.player_interval_s", "camera.player_look_radius_m"},
       [](const Scene& s) -> std::optional<std::string> {
         if (s.camera.mode == CameraMode::kPlayer) return std::nullopt;
         return "only camera.mode = player draws the player's moves, and camera.mode = " +
                mode_name(s.camera.mode);
       }},
      {{"object.size_m", "object.splits", "object.pattern", "object.pieces", "object.cluster",
        "object.gap"},
       [](const Scene& s) -> std::optional<std::string> {
         if (s.object.mesh_file.empty()) return std::nullopt;
         return "the pieces come from object.mesh_file, as the file makes them";
       }},
      {{"object.mesh_unit_m", "object.mesh_up", "object.mesh_handedness"},
       [](const Scene& s) -> std::optional<std::string> {
         if (!s.object.mesh_file.empty()) return std::nullopt;
         return "only object.mesh_file is read in these units and axes, and it is not set";
       }},
      {{"object.pieces", "object.cluster"},
       [](const Scene& s) -> std::optional<std::string> {
         if (!s.object.mesh_file.empty() || s.object.pattern != DebrisPattern::kGrid) {
           return std::nullopt;
         }
         return "only object.pattern = voronoi uses it, and object.pattern = grid";
       }},
      {{"object.splits"},
       [](const Scene& s) -> std::optional<std::string> {
         if (!s.object.mesh_file.empty() || s.object.pattern != DebrisPattern::kVoronoi) {
           return std::nullopt;
         }
         return "only object.pattern = grid uses it, and object.pattern = voronoi (object.pieces "
                "sets the count)";
       }},
      {{"ground.height_m", "ground.friction", "ground.restitution"},
       [](const Scene& s) -> std::optional<std::string> {
         if (s.ground.enabled) return std::nullopt;
         return "ground.enabled = off: there is no ground";
       }},
      {{"simulation.rest_linear_mps", "simulation.rest_angular_radps", "simulation.rest_steps"},
       [](const Scene& s) -> std::optional<std::string> {
         if (s.sim.auto_disable || s.sim.cull_resting) return std::nullopt;
         return "only simulation.auto_disable or simulation.cull_resting ask what is at rest, and "
                "both are off";
       }},
      {{"explosion.aim"},
       [](const Scene& s) -> std::optional<std::string> {
         if (s.explosion.toward_camera_mps > 0.0) return std::nullopt;
         return "only an aimed blast has an aim, and explosion.toward_camera_mps = 0";
       }},
  };
  return table;
}

}  // namespace

std::optional<std::string> why_no_effect(const Scene& scene, const std::string& key) {
  for (const Rule& r : rules()) {
    for (const std::string& k : r.keys) {
      if (k != key) continue;
      if (auto why = r.moot(scene)) return why;
    }
  }
  return std::nullopt;
}

}  // namespace fragsim
