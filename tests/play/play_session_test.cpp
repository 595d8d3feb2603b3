// The live session without a window: the camera a person flies, the flight's recording and the
// replay it must reproduce exactly (src/play).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "experiments/evaluation.hpp"
#include "play/flight_controls.hpp"
#include "play/flight_record.hpp"
#include "play/play_session.hpp"
#include "play/steered_camera.hpp"
#include "sim/camera_track_file.hpp"
#include "sim/sampled_camera.hpp"
#include "sim/scene_file.hpp"
#include "strategies/registry.hpp"
#include "support/run_fragsim.hpp"

namespace fragsim {
namespace {

constexpr double kDt = 1.0 / 60.0;

CameraPose start_pose() {
  CameraPose p;
  p.eye_m = {0.0, 1.6, 0.0};
  return p;  // looking down -z
}

TEST(FlightControls, AcceleratesAtTheBoundAndStopsAtVc) {
  CameraDef def;  // V_c 3 m/s, player_accel 20 m/s^2
  FlightControls c(def, start_pose());
  HeldControls held;
  held.forward = 1.0;
  // Speed after step n: min(20 n / 60, 3), so 3 m/s from step 9 on; the eye moves dt v per step:
  // after 9 steps z = -(1/60) (1 + ... + 9) / 3 = -0.25 m.
  CameraSample s;
  for (int n = 1; n <= 9; ++n) {
    s = c.step(held, n * kDt, kDt);
    EXPECT_NEAR(c.velocity_mps().norm(), std::min(n / 3.0, 3.0), 1e-12) << n;
  }
  EXPECT_NEAR(s.eye_m.z(), -0.25, 1e-12);
  EXPECT_NEAR(s.eye_m.x(), 0.0, 1e-15);
  held.right = 1.0;  // diagonal: no faster than V_c
  for (int n = 10; n <= 60; ++n) {
    c.step(held, n * kDt, kDt);
    EXPECT_LE(c.velocity_mps().norm(), 3.0) << n;
  }
  EXPECT_NEAR(c.velocity_mps().x(), 3.0 / std::sqrt(2.0), 1e-9);
}

TEST(FlightControls, KeysTurnAtTheTurnRate) {
  CameraDef def;  // 90 deg/s
  FlightControls c(def, start_pose());
  HeldControls held;
  held.yaw = 1.0;  // E: right
  CameraSample s;
  for (int n = 1; n <= 60; ++n) s = c.step(held, n * kDt, kDt);
  // A second at 90 deg/s: looking down +x, the right of -z; up stays world up.
  EXPECT_NEAR(s.forward.x(), 1.0, 1e-12);
  EXPECT_NEAR(s.forward.z(), 0.0, 1e-12);
  EXPECT_NEAR(s.up.y(), 1.0, 1e-12);
  held = {};
  held.mouse_pitch_rad = 0.5;  // consumed by one step
  s = c.step(held, 61 * kDt, kDt);
  EXPECT_EQ(held.mouse_pitch_rad, 0.0);
  EXPECT_NEAR(s.forward.y(), std::sin(0.5), 1e-12);
}

// A run asks a camera for step k's pose and velocity, then for k + 1's; the steered camera's
// samples replayed as a track must answer the same, bit for bit.
TEST(SteeredCamera, ReplaysBitForBitAsATrack) {
  CameraDef def;
  FlightControls c(def, start_pose());
  HeldControls held;
  SteeredCamera live(def, kDt, c.sample(0.0));
  const auto steer = [&] {
    const auto k = static_cast<int>(live.samples().size());
    held.forward = k < 40 ? 1.0 : -0.5;
    held.yaw = k > 20 ? 0.7 : 0.0;
    live.steer(c.step(held, live.next_t_s(), kDt));
  };
  std::vector<CameraPose> poses;
  std::vector<Eigen::Vector3d> velocities;
  for (int k = 0; k <= 80; ++k) {
    steer();  // the sample at (k + 1) dt: the velocity over step k needs it
    ASSERT_EQ(live.samples().size(), static_cast<std::size_t>(k + 2));
    EXPECT_EQ(live.samples()[k + 1].t_s, (k + 1) * kDt) << k;
    poses.push_back(live.pose_at(k * kDt));
    velocities.push_back(live.velocity_at(k * kDt));
  }
  const std::string csv = track_csv(def, "none", live.samples());
  const SampledCamera replay(def, parse_camera_track(csv, "flight.csv", "", def.max_speed_mps));
  for (int k = 0; k <= 80; ++k) {
    const CameraPose p = replay.pose_at(k * kDt);
    EXPECT_EQ(p.eye_m, poses[k].eye_m) << k;
    EXPECT_EQ(p.forward, poses[k].forward) << k;
    EXPECT_EQ(p.up, poses[k].up) << k;
    EXPECT_EQ(p.right, poses[k].right) << k;
    EXPECT_EQ(replay.velocity_at(k * kDt), velocities[k]) << k;
  }
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

// Flies into the blast by the step count: forward, then strafing; presses keys at given steps.
class TestPlayer final : public PlayFrontend {
 public:
  std::vector<std::pair<long, PlayEvent>> presses;
  void poll(long step, std::vector<PlayEvent>& events, HeldControls& held) override {
    held.forward = step < 60 ? 1.0 : 0.3;
    held.right = step < 60 ? 0.0 : 1.0;
    // Each press once: a new flight polls again at the step the last one ended.
    while (!presses.empty() && presses.front().first <= step) {
      events.push_back(presses.front().second);
      presses.erase(presses.begin());
    }
  }
  void present(const Image& frame) override { presented = frame.width() * frame.height(); }
  bool paced() const override { return false; }
  int presented = 0;
};

std::size_t strategy_index(const std::string& name) {
  const std::vector<std::string>& names = strategy_names();
  return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
}

// Two flights (none, then a switch to edge-min at step 70 of the session; Esc at 150): each is
// recorded, and each recording replayed by the batch tool counts what the HUD showed.
TEST(PlaySession, EveryFlightReplaysToTheHudsCounts) {
  test::UniqueDir dir("fragsim_play_session");
  const Scene scene = load_scene(std::string(FRAGSIM_DATA_DIR) + "/scenes/front.ini");
  TestPlayer player;
  player.presses = {
      {70, {PlayCommand::kChooseStrategy, static_cast<int>(strategy_index("edge-min"))}},
      {150, {PlayCommand::kQuit, 0}}};
  PlayOptions options;
  options.strategy = "none";
  options.record_folder = dir.str();
  options.style.width_px = 160;
  options.style.height_px = 90;
  PlaySession session(scene, options, player);
  std::vector<FlightReport> flights;
  session.on_flight = [&](const FlightReport& f) { flights.push_back(f); };
  session.run();

  ASSERT_EQ(flights.size(), 2u);
  EXPECT_EQ(flights[0].strategy, "none");
  EXPECT_EQ(flights[0].steps, 70);
  EXPECT_EQ(flights[1].strategy, "edge-min");
  EXPECT_EQ(flights[1].steps, 80);
  EXPECT_EQ(player.presented, 160 * 90);
  // The first flight flies into an aimed blast without protection: it must count something, or
  // the equality below would prove nothing.
  EXPECT_GT(flights[0].near_fragments + flights[0].camera_hits, 0);
  for (const FlightReport& f : flights) {
    ASSERT_TRUE(f.recorded);
    const Scene replay = load_scene(f.recorded->scene_ini);
    EXPECT_EQ(replay.step_count(), f.steps);
    EXPECT_EQ(replay.camera.mode, CameraMode::kTrack);
    EXPECT_EQ(replay.explosion.aim, ExplosionAim::kPresent);
    EvaluationOptions eval;
    eval.occlusion = false;
    const Evaluation e = evaluate(replay, f.strategy, eval);
    EXPECT_EQ(e.summary.intersections.near_fragments, f.near_fragments) << f.strategy;
    EXPECT_EQ(e.summary.intersections.camera_hit_fragments, f.camera_hits) << f.strategy;
  }
  EXPECT_EQ(flights[0].recorded->track_csv, (dir.path() / "play-001.csv").string());
  EXPECT_EQ(flights[1].recorded->track_csv, (dir.path() / "play-002.csv").string());
  // The second flight's blast is aimed at where the camera was when it went off, not at t = 0's.
  const Scene second = load_scene(flights[1].recorded->scene_ini);
  EXPECT_LT(second.camera.track_samples.front().eye_m.z(), -1.0);
}

// Holds forward from the input read after `from` steps on; quits at the read after 20.
class HoldForwardFrom final : public PlayFrontend {
 public:
  explicit HoldForwardFrom(long from) : from_(from) {}
  void poll(long step, std::vector<PlayEvent>& events, HeldControls& held) override {
    held.forward = step >= from_ ? 1.0 : 0.0;
    if (step >= 20) events.push_back({PlayCommand::kQuit, 0});
  }
  void present(const Image&) override {}
  bool paced() const override { return false; }

 private:
  long from_;
};

// The loop steers one step ahead: step k ends by asking for the camera's velocity over step
// k + 1, so what is held when the input is read after k steps first moves the camera in step
// k + 1, the sample at (k + 2) dt.
TEST(PlaySession, KeysReadAfterStepKMoveTheCameraFromStepKPlusOne) {
  test::UniqueDir dir("fragsim_play_ahead");
  const Scene scene = load_scene(std::string(FRAGSIM_DATA_DIR) + "/scenes/front.ini");
  HoldForwardFrom player(10);
  PlayOptions options;
  options.strategy = "none";
  options.record_folder = dir.str();
  options.style.width_px = 32;
  options.style.height_px = 18;
  PlaySession session(scene, options, player);
  std::vector<FlightReport> flights;
  session.on_flight = [&](const FlightReport& f) { flights.push_back(f); };
  session.run();

  ASSERT_EQ(flights.size(), 1u);
  EXPECT_EQ(flights[0].steps, 20);
  ASSERT_TRUE(flights[0].recorded);
  const std::vector<CameraSample> track =
      load_camera_track(flights[0].recorded->track_csv, "", scene.camera.max_speed_mps);
  // t = 0 to 21 dt: the last step asked for the velocity at its end.
  ASSERT_EQ(track.size(), 22u);
  for (std::size_t k = 0; k <= 11; ++k) EXPECT_EQ(track[k].eye_m, track[0].eye_m) << k;
  EXPECT_GT((track[12].eye_m - track[11].eye_m).norm(), 0.0);
  for (std::size_t k = 12; k < track.size(); ++k) {
    EXPECT_GT((track[k].eye_m - track[k - 1].eye_m).norm(), 0.0) << k;
  }
}

}  // namespace
}  // namespace fragsim

namespace fragsim {
namespace {

// Bad options are one line naming the option, exit status 2, before any window opens.
TEST(PlayCommand, BadOptionsAreOneLineAndStatus2) {
  const std::string scene = "--scene " + std::string(FRAGSIM_DATA_DIR) + "/scenes/front.ini ";
  for (const auto& [args, named] : std::vector<std::pair<std::string, std::string>>{
           {"--bench-frames 0", "--bench-frames"},
           {"--bench-frames x", "--bench-frames"},
           {"--record flight.ini", "--record"},
           {"--record /nonexistent-folder/f.csv", "--record"},
           {"--size 10x10", "--size"},
           {"--overlays stars", "--overlays"},
           {"--strategy nosuch", "--strategy"}}) {
    const test::Result r = test::run_fragsim("play " + scene + args);
    EXPECT_EQ(r.status, 2) << args << ": " << r.out;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << args << ": " << r.out;
    EXPECT_NE(r.out.find(named), std::string::npos) << args << ": " << r.out;
  }
}

// The benchmark mode flies the scripted route headless and reports every part of a frame.
TEST(PlayCommand, BenchFramesRunsHeadlessAndRecordsNothing) {
  test::UniqueDir dir("fragsim_play_bench");
  const test::Result r = test::run_fragsim("play --scene " + std::string(FRAGSIM_DATA_DIR) +
                                           "/scenes/thesis125.ini --bench-frames 30 "
                                           "--strategy edge --size 64x36 --record " +
                                           dir.str() + "/f.csv");
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("flight 1: edge, 0.500 s (30 steps)"), std::string::npos) << r.out;
  // 31 frames: the explosion's and one per step.
  EXPECT_NE(r.out.find("frames: 31, median / p95 ms: frame "), std::string::npos) << r.out;
  for (const char* part : {"physics", "strategy", "draw", "present"}) {
    EXPECT_NE(r.out.find(std::string("; ") + part + " "), std::string::npos) << part;
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

}  // namespace
}  // namespace fragsim
