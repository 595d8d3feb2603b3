// Camera tracks from CSV files: what is read, what is refused (one line naming file:line), and a
// path run's camera.csv replayed as a track reproducing that run.

#include "sim/camera_track_file.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "experiments/evaluation.hpp"
#include "io/input_file.hpp"
#include "report/csv_export.hpp"
#include "sim/scene_file.hpp"

namespace fragsim {
namespace {

const std::string kHeader =
    "t_s,eye_x_m,eye_y_m,eye_z_m,forward_x,forward_y,forward_z,up_x,up_y,up_z";

std::string error_of(const std::string& text, const std::string& strategy = "",
                     double max_speed_mps = 3.0) {
  try {
    parse_camera_track(text, "track.csv", strategy, max_speed_mps);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CameraTrackFile, ReadsColumnsInAnyOrderAndIgnoresOthers) {
  const std::string text =
      "up_x,up_y,up_z,note,t_s,eye_x_m,eye_y_m,eye_z_m,forward_x,forward_y,forward_z\n"
      "0,1,0,start,0,0,1.6,0,0,0,-1\n"
      "0,1,0,later,0.5,1,1.6,0,1,0,0\n";
  const auto s = parse_camera_track(text, "t.csv", "", 3.0);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[1].t_s, 0.5);
  EXPECT_EQ(s[1].eye_m, Eigen::Vector3d(1, 1.6, 0));
  EXPECT_EQ(s[1].forward, Eigen::Vector3d(1, 0, 0));
}

TEST(CameraTrackFile, StrategyColumnSelectsRows) {
  const std::string text = "strategy," + kHeader +
                           "\n"
                           "none,0,0,1,0,0,0,-1,0,1,0\n"
                           "none,1,0,1,-1,0,0,-1,0,1,0\n"
                           "edge,0,5,1,0,0,0,-1,0,1,0\n"
                           "edge,1,5,1,-2,0,0,-1,0,1,0\n";
  EXPECT_EQ(parse_camera_track(text, "t.csv", "", 3.0).front().eye_m.x(), 0.0);  // the first
  EXPECT_EQ(parse_camera_track(text, "t.csv", "edge", 3.0).front().eye_m.x(), 5.0);
  EXPECT_EQ(error_of(text, "wall"), "track.csv: no samples for strategy 'wall'");
  EXPECT_EQ(error_of(kHeader + "\n0,0,1,0,0,0,-1,0,1,0\n", "edge"),
            "track.csv:1: camera.track_strategy = 'edge' but the file has no 'strategy' column");
}

TEST(CameraTrackFile, BadFilesNameTheLine) {
  EXPECT_EQ(error_of("t_s,eye_x_m\n0,0\n"), "track.csv:1: missing column 'eye_y_m'");
  EXPECT_EQ(error_of(kHeader + "\n0,0,1,0,0,0,-1,0,1,0\n0.1,0,1,nan,0,0,-1,0,1,0\n"),
            "track.csv:3: eye_z_m = 'nan': not a finite number");
  EXPECT_EQ(error_of(kHeader + "\n0,0,1,0,0,0,-1,0,1,0\n0,0,1,0,0,0,-1,0,1,0\n"),
            "track.csv:3: t_s = 0: time must increase strictly (previous 0)");
  EXPECT_EQ(error_of(kHeader + "\n0,0,1,0,0,0,-1,0,1,0.001\n"),
            "track.csv:2: forward and up are not unit and orthogonal to 1e-6 (|forward| = 1, "
            "|up| = 1.000000499999875, forward.up = -0.001)");
  // 0.5 m in 0.1 s is 5 m/s, above V_c = 3 m/s: the strategies rely on V_c.
  EXPECT_EQ(error_of(kHeader + "\n0,0,1,0,0,0,-1,0,1,0\n0.1,0.5,1,0,0,0,-1,0,1,0\n"),
            "track.csv:3: speed 5 m/s between t = 0 s and t = 0.1 s is above "
            "camera.max_speed_mps = 3");
  EXPECT_EQ(error_of(kHeader + "\n0,0,1\n"), "track.csv:2: 3 cells, the header has 10");
  EXPECT_EQ(error_of(""), "track.csv: empty camera track (expected a header row)");
  EXPECT_EQ(error_of(kHeader + "\n"), "track.csv: no samples");
}

TEST(CameraTrackFile, FilesGoThroughTheOneDoor) {
  try {
    load_camera_track("/tmp", "", 3.0);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "/tmp: is a directory, not a camera track");
  }
  const std::string path = ::testing::TempDir() + "/bom_track.csv";
  {
    std::ofstream out(path, std::ios::binary);
    out << "\xEF\xBB\xBF" << kHeader << "\r\n0,0,1,0,0,0,-1,0,1,0\r\n";
  }
  EXPECT_EQ(load_camera_track(path, "", 3.0).size(), 1u);
  std::remove(path.c_str());
}

TEST(CameraTrackFile, SceneNamesABadTrackAndItsKey) {
  try {
    load_scene("", {{"camera.mode", "track"}, {"camera.track_file", "/nonexistent.csv"}});
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), "/nonexistent.csv: no such camera track (camera.track_file)");
  }
  try {
    load_scene("", {{"camera.mode", "track"}});
    FAIL();
  } catch (const SceneError& e) {
    EXPECT_EQ(std::string(e.what()), "camera.track_file: needed with camera.mode = track");
  }
}

// A track named in a scene file is found beside it, as object.mesh_file is; on the command line a
// relative path is the current folder's.
TEST(CameraTrackFile, RelativeTrackFileIsTakenFromTheSceneFilesFolder) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("fragsim_track_" + std::to_string(::getpid()));
  fs::create_directories(dir / "flights");
  std::ofstream(dir / "flights" / "t.csv") << kHeader << "\n0,0,1,0,0,0,-1,0,1,0\n";
  std::ofstream(dir / "flights" / "t.ini") << "[camera]\nmode = track\ntrack_file = t.csv\n";
  const Scene s = load_scene((dir / "flights" / "t.ini").string());
  EXPECT_EQ(s.camera.track_file, (dir / "flights" / "t.csv").string());
  EXPECT_EQ(s.camera.track_samples.size(), 1u);
  const fs::path cwd = fs::current_path();
  fs::current_path(dir);
  const Scene cli =
      load_scene("", {{"camera.mode", "track"}, {"camera.track_file", "flights/t.csv"}});
  fs::current_path(cwd);
  EXPECT_EQ(cli.camera.track_file, (dir / "flights" / "t.csv").string());
  EXPECT_EQ(cli.camera.track_samples.size(), 1u);
  fs::remove_all(dir);
}

// The camera.csv of a path run, replayed as a track, gives that run's counts for every strategy.
TEST(CameraTrackFile, ReplayedPathRunReproducesItsCounts) {
  const Scene path_scene = load_scene(std::string(FRAGSIM_DATA_DIR) + "/scenes/front.ini");
  const std::vector<std::string> all{"none",       "wall", "deflect-all",
                                     "near-plane", "edge", "edge-min"};
  const std::vector<Evaluation> path_runs = compare(path_scene, all, false, nullptr, 2);
  Scene track_scene = path_scene;
  track_scene.camera.mode = CameraMode::kTrack;
  track_scene.camera.track_samples = parse_camera_track(
      camera_csv(path_scene, path_runs), "camera.csv", "none", path_scene.camera.max_speed_mps);
  const std::vector<Evaluation> track_runs = compare(track_scene, all, false, nullptr, 2);
  ASSERT_EQ(track_runs.size(), path_runs.size());
  for (std::size_t i = 0; i < path_runs.size(); ++i) {
    const RunSummary& a = path_runs[i].summary;
    const RunSummary& b = track_runs[i].summary;
    EXPECT_EQ(a.intersections.near_fragments, b.intersections.near_fragments) << a.strategy;
    EXPECT_EQ(a.intersections.camera_hit_fragments, b.intersections.camera_hit_fragments)
        << a.strategy;
    EXPECT_EQ(a.intersections.near_misses, b.intersections.near_misses) << a.strategy;
  }
}

}  // namespace
}  // namespace fragsim
