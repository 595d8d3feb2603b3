// What a flight leaves behind, checked before anyone flies: a --record path that cannot be
// written is named at once (it was found only when the first flight ended), and a recording
// replays without a warning; each flight's files are numbered and never overwrite another's.

#include "play/flight_record.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "sim/scene_file.hpp"
#include "support/run_fragsim.hpp"

namespace fragsim {
namespace {

namespace fs = std::filesystem;

TEST(FlightRecord, UnwritablePathIsFoundBeforeFlying) {
  // /proc takes no new files, not even root's.
  const auto proc = record_path_problem("/proc/fragsim_flight.csv", "");
  ASSERT_TRUE(proc);
  EXPECT_EQ(*proc, "/proc/fragsim_flight.csv: cannot write (No such file or directory)");
  test::UniqueDir dir("fragsim_record_probe");
  fs::create_directory(dir.path() / "taken.csv");
  EXPECT_EQ(record_path_problem((dir.path() / "taken.csv").string(), ""),
            (dir.path() / "taken.csv").string() + " is a folder");
  fs::create_directory(dir.path() / "taken.ini");
  EXPECT_EQ(record_path_problem("", dir.str()), std::nullopt);  // play-001.* are free
  EXPECT_EQ(record_path_problem((dir.path() / "ok.csv").string(), ""), std::nullopt);
  // The probe leaves nothing behind.
  std::vector<std::string> left;
  for (const auto& e : fs::directory_iterator(dir.path())) left.push_back(e.path().filename());
  std::sort(left.begin(), left.end());
  EXPECT_EQ(left, (std::vector<std::string>{"taken.csv", "taken.ini"}));
}

// The command refuses it in one line naming --record, before it opens a window.
TEST(FlightRecord, PlayCommandRefusesAnUnwritableRecordBeforeTheWindow) {
  const test::Result r = test::run_fragsim("play --record /proc/fragsim_flight.csv");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_EQ(r.out,
            "fragsim play: --record /proc/fragsim_flight.csv: /proc/fragsim_flight.csv: cannot "
            "write (No such file or directory)\n");
}

// A recording's track covers its replay's run, and its scene is fragsim's own: no warning.
TEST(FlightRecord, RecordingReplaysWithoutWarnings) {
  test::UniqueDir dir("fragsim_record_replay");
  const Scene flight;
  const int steps = 30;
  std::vector<CameraSample> samples;
  for (int k = 0; k <= steps; ++k) {
    CameraSample s;
    s.t_s = k * flight.sim.dt_s;
    s.eye_m = {0.0, 1.6, -k * flight.sim.dt_s};
    s.forward = {0.0, 0.0, -1.0};
    s.up = {0.0, 1.0, 0.0};
    samples.push_back(s);
  }
  const RecordPaths paths = record_paths("", 1, dir.str());
  write_flight(paths, flight, "none", samples, steps);
  std::vector<std::string> warnings;
  const Scene replay = load_scene(paths.scene_ini, {}, &warnings);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  EXPECT_EQ(replay.camera.track_samples.size(), samples.size());
}

TEST(FlightRecord, NumbersNeverOverwriteAndRequestedNamesCount) {
  test::UniqueDir dir("fragsim_play_paths");
  const auto touch = [&](const char* name) { std::ofstream(dir.path() / name) << "x"; };
  EXPECT_EQ(record_paths("", 1, dir.str()).track_csv, (dir.path() / "play-001.csv").string());
  touch("play-001.csv");
  touch("play-002.ini");  // a scene alone still takes its number
  const RecordPaths p = record_paths("", 7, dir.str());
  EXPECT_EQ(p.track_csv, (dir.path() / "play-003.csv").string());
  EXPECT_EQ(p.scene_ini, (dir.path() / "play-003.ini").string());
  EXPECT_EQ(record_paths("out/f.csv", 1, "").track_csv, "out/f.csv");
  EXPECT_EQ(record_paths("out/f.csv", 1, "").scene_ini, "out/f.ini");
  EXPECT_EQ(record_paths("out/f.csv", 3, "").track_csv, "out/f-3.csv");
  EXPECT_EQ(record_paths("out/f.csv", 3, "").scene_ini, "out/f-3.ini");
}

}  // namespace
}  // namespace fragsim
