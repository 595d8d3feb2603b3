#include "play/flight_record.hpp"

#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "io/atomic_file.hpp"
#include "report/csv_export.hpp"
#include "sim/scene_file.hpp"

namespace fragsim {
namespace fs = std::filesystem;

namespace {

std::string ini_beside(const fs::path& csv) {
  fs::path p = csv;
  p.replace_extension(".ini");
  return p.string();
}

}  // namespace

std::string track_csv(const CameraDef& camera, const std::string& strategy,
                      const std::vector<CameraSample>& samples) {
  std::string out = camera_csv_header();
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const CameraSample& s = samples[k];
    CameraPose pose;
    pose.eye_m = s.eye_m;
    pose.forward = s.forward;
    pose.up = s.up;
    // The scene's near plane, as pulling it in changes what a strategy renders, not the track.
    pose.near_m = camera.near_m;
    pose.fovy_deg = camera.fovy_deg;
    pose.aspect = camera.aspect;
    append_camera_row(out, strategy, k, s.t_s, pose);
  }
  return out;
}

Scene replay_scene(const Scene& flight, const std::string& track_path, int steps) {
  Scene s = flight;
  s.camera.mode = CameraMode::kTrack;
  s.camera.track_file = fs::absolute(track_path).lexically_normal().string();
  s.camera.track_strategy.clear();
  s.camera.track_samples.clear();
  s.explosion.aim = ExplosionAim::kPresent;
  s.sim.duration_s = steps * s.sim.dt_s;
  return s;
}

RecordPaths record_paths(const std::string& requested, int flight, const std::string& folder) {
  if (!requested.empty()) {
    fs::path p(requested);
    if (flight > 1) {
      p.replace_filename(p.stem().string() + "-" + std::to_string(flight) + p.extension().string());
    }
    return {p.string(), ini_beside(p)};
  }
  for (int n = 1;; ++n) {
    char name[32];
    std::snprintf(name, sizeof name, "play-%03d.csv", n);
    const fs::path p = folder.empty() ? fs::path(name) : fs::path(folder) / name;
    std::error_code ec;
    if (!fs::exists(p, ec) && !fs::exists(ini_beside(p), ec)) return {p.string(), ini_beside(p)};
  }
}

std::optional<std::string> record_path_problem(const std::string& requested,
                                               const std::string& folder) {
  const RecordPaths paths = record_paths(requested, 1, folder);
  for (const std::string& path : {paths.track_csv, paths.scene_ini}) {
    std::error_code ec;
    if (fs::is_directory(path, ec)) return path + " is a folder";
    try {
      AtomicFile probe(path);  // destroyed uncommitted, so its temporary file is removed
    } catch (const std::runtime_error& e) {
      return e.what();
    }
  }
  return std::nullopt;
}

void write_flight(const RecordPaths& paths, const Scene& flight, const std::string& strategy,
                  const std::vector<CameraSample>& samples, int steps) {
  write_file_atomically(paths.track_csv, track_csv(flight.camera, strategy, samples));
  write_file_atomically(paths.scene_ini,
                        scene_to_ini(replay_scene(flight, paths.track_csv, steps)));
}

}  // namespace fragsim
