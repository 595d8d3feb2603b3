// Camera tracks from CSV files: what is read, what is refused (one line naming file:line), and a
// path run's camera.csv replayed as a track reproducing that run.

#include "sim/camera_track_file.hpp"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <optional>
#include <string>

#include "experiments/evaluation.hpp"
#include "io/input_file.hpp"
#include "io/number_format.hpp"
#include "report/csv_export.hpp"
#include "report/results_table.hpp"
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
  EXPECT_EQ(error_of("t_s,eye_x_m\n0,0\n"),
            "track.csv:1: missing column 'eye_y_m'; the header read was: t_s,eye_x_m; expected "
            "comma-separated names: "
            "t_s,eye_x_m,eye_y_m,eye_z_m,forward_x,forward_y,forward_z,up_x,up_y,up_z");
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

// A track that does not cover the run [0, 3] s leaves the camera standing still where it does
// not: each of the four ways an export misses it gets one line saying what the track covers and
// what the run needs.
std::optional<std::string> coverage_of(const std::string& rows,
                                       TrackTime time = TrackTime::kAsRecorded) {
  CameraTrackReading reading;
  reading.max_speed_mps = 3.0;
  reading.time = time;
  return track_coverage_warning(parse_camera_track(kHeader + "\n" + rows, "t.csv", reading), 3.0,
                                time, "t.csv");
}

TEST(CameraTrackFile, EachTrackThatMissesTheRunIsNamed) {
  // Engine-clock times: 73.2 to 76.2 s.
  const std::string engine = "73.2,0,1,0,0,0,-1,0,1,0\n76.2,0,1,-3,0,0,-1,0,1,0\n";
  EXPECT_EQ(coverage_of(engine),
            "camera track t.csv covers t = 73.2 to 76.2 s, the run needs t = 0 to 3 s: the camera "
            "stands still for the whole run (times are read as recorded, t = 0 the blast; "
            "camera.track_time = from_first_sample starts the track at t = 0)");
  // All times negative.
  EXPECT_EQ(coverage_of("-5,0,1,0,0,0,-1,0,1,0\n-3,0,1,-3,0,0,-1,0,1,0\n"),
            "camera track t.csv covers t = -5 to -3 s, the run needs t = 0 to 3 s: the camera "
            "stands still for the whole run (times are read as recorded, t = 0 the blast; "
            "camera.track_time = from_first_sample starts the track at t = 0)");
  // One row.
  EXPECT_EQ(coverage_of("0,0,1,0,0,0,-1,0,1,0\n"),
            "camera track t.csv has one sample (t = 0 s), the run needs t = 0 to 3 s: the camera "
            "stands still for the whole run");
  // A recording cut short: shifting it would not help, so nothing is suggested.
  EXPECT_EQ(coverage_of("0,0,1,0,0,0,-1,0,1,0\n2,0,1,-2,0,0,-1,0,1,0\n"),
            "camera track t.csv covers t = 0 to 2 s, the run needs t = 0 to 3 s: the camera "
            "stands still from t = 2 s on");
  EXPECT_EQ(coverage_of("1,0,1,0,0,0,-1,0,1,0\n3,0,1,-2,0,0,-1,0,1,0\n"),
            "camera track t.csv covers t = 1 to 3 s, the run needs t = 0 to 3 s: the camera "
            "stands still until t = 1 s");  // shifted, it would end at 2 s: no better
  // A track over the run, and the engine's clip read from its first sample, say nothing.
  EXPECT_EQ(coverage_of("-1,0,1,0,0,0,-1,0,1,0\n3,0,1,-3,0,0,-1,0,1,0\n"), std::nullopt);
  EXPECT_EQ(coverage_of(engine, TrackTime::kFromFirstSample), std::nullopt);
}

TEST(CameraTrackFile, FromFirstSampleShiftsTimesOnly) {
  CameraTrackReading reading;
  reading.max_speed_mps = 3.0;
  reading.time = TrackTime::kFromFirstSample;
  const auto s = parse_camera_track(
      kHeader + "\n73.25,0,1,0,0,0,-1,0,1,0\n74.5,0,1,-1,0,0,-1,0,1,0\n", "t.csv", reading);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].t_s, 0.0);
  EXPECT_EQ(s[1].t_s, 1.25);
  EXPECT_EQ(s[1].eye_m, Eigen::Vector3d(0, 1, -1));
}

// The scene names the key, warns on loading (what the CLI prints on stderr) and in the text
// table's header; the CSV has no room for it and stays as it was.
TEST(CameraTrackFile, SceneWarnsAndTheTableHeaderSaysSo) {
  const std::string path = ::testing::TempDir() + "/engine_clock.csv";
  std::ofstream(path) << kHeader << "\n73.2,0,1,0,0,0,-1,0,1,0\n73.7,0,1,-1,0,0,-1,0,1,0\n";
  std::vector<std::string> warnings;
  const Scene s = load_scene("",
                             {{"camera.mode", "track"},
                              {"camera.track_file", path},
                              {"simulation.duration_s", "0.5"},
                              {"object.splits", "2"}},
                             &warnings);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], "camera track " + path +
                             " covers t = 73.2 to 73.7 s, the run needs t = 0 to 0.5 s: the camera "
                             "stands still for the whole run (times are read as recorded, t = 0 "
                             "the blast; camera.track_time = from_first_sample starts the track "
                             "at t = 0)");
  const std::vector<Evaluation> runs = compare(s, {"none"}, false, nullptr, 1);
  const ResultsTable table = results_table(s, runs);
  const std::string text = results_text(table);
  EXPECT_EQ(text.find("warning: " + warnings[0] + "\n"), text.find('\n') + 1) << text;
  EXPECT_EQ(results_csv(table, false).find("warning"), std::string::npos);

  warnings.clear();
  const Scene shifted = load_scene("",
                                   {{"camera.mode", "track"},
                                    {"camera.track_file", path},
                                    {"camera.track_time", "from_first_sample"},
                                    {"simulation.duration_s", "0.5"},
                                    {"object.splits", "2"}},
                                   &warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  EXPECT_EQ(results_text(results_table(shifted, runs)).find("warning"), std::string::npos);
  std::remove(path.c_str());
}

// A header split on ';' or written with quotes said "missing column 't_s'" while the column was
// there: the message shows what was read and what is expected; double-quoted names are read.
TEST(CameraTrackFile, HeaderMessagesShowWhatWasReadAndQuotedNamesAreRead) {
  EXPECT_EQ(error_of("\"t_s\";\"eye_x_m\";\"eye_y_m\"\n0;0;1\n"),
            "track.csv:1: missing column 't_s'; the header read was: "
            "\"t_s\";\"eye_x_m\";\"eye_y_m\"; expected comma-separated names: "
            "t_s,eye_x_m,eye_y_m,eye_z_m,forward_x,forward_y,forward_z,up_x,up_y,up_z");
  std::string quoted;
  for (const char* name : {"t_s", "eye_x_m", "eye_y_m", "eye_z_m", "forward_x", "forward_y",
                           "forward_z", "up_x", "up_y", "up_z"}) {
    quoted += (quoted.empty() ? "\"" : ",\"") + std::string(name) + "\"";
  }
  const auto s = parse_camera_track(quoted + "\n0,0,1,0,0,0,-1,0,1,0\n", "t.csv", "", 3.0);
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0].eye_m, Eigen::Vector3d(0, 1, 0));
}

// Spreadsheets and pandas quote every cell: read as RFC 4180 says, a quoted cell may hold commas
// and "" for a quote; a quote left open is named.
TEST(CameraTrackFile, QuotedCellsAreReadAsRfc4180Says) {
  std::string quoted;
  for (const char* name : {"t_s", "eye_x_m", "eye_y_m", "eye_z_m", "forward_x", "forward_y",
                           "forward_z", "up_x", "up_y", "up_z", "note"}) {
    quoted += (quoted.empty() ? "\"" : ",\"") + std::string(name) + "\"";
  }
  const std::string row =
      "\"0.0\",\"0\",\"1\",\"0\",\"0\",\"0\",\"-1\",\"0\",\"1\",\"0\",\"a, \"\"b\"\"\"\n"
      "\"0.5\", \"1\" ,\"1\",\"0\",\"0\",\"0\",\"-1\",\"0\",\"1\",\"0\",\"\"\n";
  const auto s = parse_camera_track(quoted + "\n" + row, "t.csv", "", 3.0);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[1].t_s, 0.5);
  EXPECT_EQ(s[1].eye_m, Eigen::Vector3d(1, 1, 0));
  EXPECT_EQ(error_of(kHeader + "\n\"0,0,1,0,0,0,-1,0,1,0\n"),
            "track.csv:2: a quoted cell is not closed, or has text after its closing quote");
  EXPECT_EQ(error_of(kHeader + "\n\"0\"x,0,1,0,0,0,-1,0,1,0\n"),
            "track.csv:2: a quoted cell is not closed, or has text after its closing quote");
}

// A track in centimetres or millimetres, or Z-up, read as fragsim's own is far too fast: the
// message says which key reads it right.
TEST(CameraTrackFile, TooFastTracksNameTheUnitOrAxisKey) {
  // 50 units in 0.1 s: 500 m/s, 167 times the 3 m/s bound: centimetres.
  EXPECT_EQ(error_of(kHeader + "\n0,0,100,0,0,0,-1,0,1,0\n0.1,50,100,0,0,0,-1,0,1,0\n"),
            "track.csv:3: speed 500 m/s between t = 0 s and t = 0.1 s is above "
            "camera.max_speed_mps = 3; about 100 times the bound: a track in other units needs "
            "camera.track_unit_m = 0.01 (centimetres)");
  // 3,000 m/s: millimetres.
  EXPECT_NE(error_of(kHeader + "\n0,0,1,0,0,0,-1,0,1,0\n0.1,300,1,0,0,0,-1,0,1,0\n")
                .find("3000 m/s between t = 0 s and t = 0.1 s is above camera.max_speed_mps = 3; "
                      "about 1000 times the bound: a track in other units needs "
                      "camera.track_unit_m = 0.001 (millimetres)"),
            std::string::npos);
  // Up along z, as Unreal and Blender write a camera: the up axis's key too.
  EXPECT_EQ(error_of(kHeader + "\n0,0,0,160,0,1,0,0,0,1\n0.1,50,0,160,0,1,0,0,0,1\n"),
            "track.csv:3: speed 500 m/s between t = 0 s and t = 0.1 s is above "
            "camera.max_speed_mps = 3; about 100 times the bound: a track in other units needs "
            "camera.track_unit_m = 0.01 (centimetres); its up vectors point along z: a Z-up "
            "track (Unreal, Blender) needs camera.track_up = z");
}

// A NUL byte in a cell no longer cuts the message short.
TEST(CameraTrackFile, ControlCharactersInACellAreShown) {
  const std::string row("0,0,1,0\0x,0,0,-1,0,1,0\n", 23);
  EXPECT_EQ(error_of(kHeader + "\n" + row),
            "track.csv:2: eye_z_m = '0\\x00x': not a finite number");
}

// The same track written Y-up in metres (fragsim's frame), Z-up in centimetres (right- and
// left-handed, Blender's and Unreal's axes) and Y-up left-handed (Unity's) gives the same run,
// byte for byte: positions are multiples of 1/64 m, so every unit and axis change is exact.
TEST(CameraTrackFile, UnitsAndAxesRoundTripToTheSameRun) {
  struct Frame {
    std::string name;
    std::vector<SceneOverride> keys;
    // fragsim's (x, y, z) as the file writes it, before the unit
    std::function<Eigen::Vector3d(const Eigen::Vector3d&)> from_fragsim;
    double per_m = 1.0;
  };
  const std::vector<Frame> frames{
      {"yup_m", {}, [](const Eigen::Vector3d& v) { return v; }},
      {"zup_cm_right",
       {{"camera.track_unit_m", "0.01"}, {"camera.track_up", "z"}},
       [](const Eigen::Vector3d& v) { return Eigen::Vector3d(v.x(), -v.z(), v.y()); },
       100.0},
      {"zup_cm_left",
       {{"camera.track_unit_m", "0.01"},
        {"camera.track_up", "z"},
        {"camera.track_handedness", "left"}},
       [](const Eigen::Vector3d& v) { return Eigen::Vector3d(v.x(), v.z(), v.y()); },
       100.0},
      {"yup_m_left",
       {{"camera.track_handedness", "left"}},
       [](const Eigen::Vector3d& v) { return Eigen::Vector3d(v.x(), v.y(), -v.z()); }},
  };
  const auto number = [](double v) { return format_double(v); };
  std::vector<std::string> camera_files, summary_files;
  for (const Frame& f : frames) {
    std::string text = kHeader + "\n";
    for (int k = 0; k <= 4; ++k) {
      // 1/64 m steps; the view turns from straight ahead to a right angle (exact components).
      const Eigen::Vector3d eye(k * 5.0 / 64.0, 1.5 + k / 64.0, -k * 40.0 / 64.0);
      const Eigen::Vector3d forward = k < 2 ? Eigen::Vector3d(0, 0, -1) : Eigen::Vector3d(-1, 0, 0);
      const Eigen::Vector3d up(0, 1, 0);
      const Eigen::Vector3d e = f.from_fragsim(eye) * f.per_m;
      const Eigen::Vector3d fw = f.from_fragsim(forward);
      const Eigen::Vector3d u = f.from_fragsim(up);
      text += number(k * 0.25);
      for (const Eigen::Vector3d* v : {&e, &fw, &u}) {
        for (int i = 0; i < 3; ++i) text += "," + number((*v)[i]);
      }
      text += "\n";
    }
    const std::string path = ::testing::TempDir() + "/track_" + f.name + ".csv";
    std::ofstream(path) << text;
    std::vector<SceneOverride> keys{{"camera.mode", "track"},
                                    {"camera.track_file", path},
                                    {"simulation.duration_s", "1"},
                                    {"object.splits", "3"}};
    keys.insert(keys.end(), f.keys.begin(), f.keys.end());
    const Scene s = load_scene("", keys);
    const std::vector<Evaluation> runs = compare(s, {"none", "edge"}, false, nullptr, 1);
    camera_files.push_back(camera_csv(s, runs));
    summary_files.push_back(summary_csv(s, runs));
    std::remove(path.c_str());
  }
  for (std::size_t i = 1; i < frames.size(); ++i) {
    EXPECT_EQ(camera_files[i], camera_files[0]) << frames[i].name;
    EXPECT_EQ(summary_files[i], summary_files[0]) << frames[i].name;
  }
  EXPECT_NE(camera_files[0].find(",0.078125,1.515625,-0.625,"), std::string::npos)
      << camera_files[0];
}

}  // namespace
}  // namespace fragsim
