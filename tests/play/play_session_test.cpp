// The live session without a window (play/play_session.cpp): each flight's recording replays to
// the HUD's counts, and keys move the camera from the next step. The camera a person flies, its
// samples and its record are tested beside their own sources in tests/play/.

#include "play/play_session.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "experiments/evaluation.hpp"
#include "play/flight_record.hpp"
#include "sim/camera_track_file.hpp"
#include "sim/scene_file.hpp"
#include "strategies/registry.hpp"
#include "support/run_fragsim.hpp"

namespace fragsim {
namespace {

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
