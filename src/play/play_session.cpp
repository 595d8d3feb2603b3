#include "play/play_session.hpp"

#include <chrono>
#include <cstdio>
#include <deque>
#include <filesystem>
#include <thread>

#include "metrics/near_plane_metric.hpp"
#include "play/hud.hpp"
#include "play/steered_camera.hpp"
#include "sim/camera_motion.hpp"
#include "sim/explosion.hpp"
#include "sim/run.hpp"
#include "sim/scene_strategies.hpp"

namespace fragsim {
namespace {

using Clock = std::chrono::steady_clock;
double ms_between(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

// A flight's longest is simulation.duration_s's upper bound, so its replay scene is valid.
constexpr double kMaxFlightS = 3600.0;
// A window shows at most one frame per 60 Hz refresh; finer steps are simulated, not drawn.
constexpr double kFrameS = 1.0 / 60.0;
// The time rate the HUD shows is measured over this much wall time.
constexpr double kRateWindowS = 1.0;

// What the player's input asks of a flight, to go on or to end it and then quit or fly `strategy`.
struct Ask {
  enum class Kind { kFlyOn, kQuit, kFly } kind = Kind::kFlyOn;
  std::size_t strategy = 0;  // the next flight's, for kFly
};

Scene scene_as_flown(const Scene& scene) {
  Scene s = scene;
  // The object stays where the scene put it relative to the scene's camera; each flight's blast
  // is aimed at where the steered camera is when it goes off.
  s.object.centre_m = object_centre(scene);
  s.object.distance_m = 0.0;
  s.explosion.aim = ExplosionAim::kPresent;
  s.sim.duration_s = kMaxFlightS;
  s.camera.mode = CameraMode::kTrack;
  s.camera.track_file.clear();
  s.camera.track_strategy.clear();
  s.camera.track_samples.clear();
  return s;
}

std::string numbered_png(const std::string& folder) {
  for (int n = 1;; ++n) {
    char name[32];
    std::snprintf(name, sizeof name, "play-shot-%03d.png", n);
    const std::filesystem::path p =
        folder.empty() ? std::filesystem::path(name) : std::filesystem::path(folder) / name;
    std::error_code ec;
    if (!std::filesystem::exists(p, ec)) return p.string();
  }
}

}  // namespace

class PlaySession::Flight {
 public:
  Flight(PlaySession& session, const NearPlaneMetric& near, std::string strategy,
         FrameRenderer& with_overlays, FrameRenderer& without)
      : s_(session),
        near_(near),
        with_(with_overlays),
        without_(without),
        strategy_(std::move(strategy)) {}

  // The flight's loop reads the input, draws and steps once per state (the explosion's, then each
  // step's). It ends when the player ends the flight, when the session's max_steps are flown, or
  // when the run's hour is up (then the same strategy flies again).
  Ask fly(Run& run, SteeredCamera& camera) {
    const double dt = s_.flight_scene_.sim.dt_s;
    hud_.strategy = strategy_;
    last_end_ = Clock::now();
    wall_base_ = last_end_;
    t_base_ = 0.0;
    rate_.clear();
    for (bool first = true;; first = false) {
      const StepSnapshot& snap = run.state();
      update_hud(snap);
      Ask ask;
      const bool redraw = poll(ask);
      if (ask.kind != Ask::Kind::kFlyOn) return ask;
      const bool due = first || snap.t_s - last_drawn_t_s_ >= kFrameS - 1e-9;
      if (due || redraw) draw(snap, due);
      if (s_.options_.max_steps > 0 && s_.session_steps_ >= s_.options_.max_steps) {
        return {Ask::Kind::kQuit, 0};
      }
      if (due) pace(snap.t_s);
      ask = wait_while_paused(snap);
      if (ask.kind != Ask::Kind::kFlyOn) return ask;
      if (run.done()) return {Ask::Kind::kFly, s_.current_};

      // Step k ends by asking for the velocity over step k + 1, so the camera is steered one step
      // ahead, and what is held then moves it during step k + 1 (the sample at (k + 2) dt).
      camera.steer(s_.controls_.step(s_.held_, camera.next_t_s(), dt));
      run.step();
      ++s_.session_steps_;
      physics_ms_ += 1e3 * run.state().physics_s;
      strategy_ms_ += 1e3 * run.state().strategy_s;
    }
  }

 private:
  void update_hud(const StepSnapshot& snap) {
    RunSummary counts;
    near_.fill(counts);
    hud_.t_s = snap.t_s;
    hud_.near_fragments = counts.intersections.near_fragments;
    hud_.camera_hits = counts.intersections.camera_hit_fragments;
    hud_.candidates = static_cast<int>(snap.candidates.size());
    hud_.strategy_ms = 1e3 * snap.strategy_s;
    hud_.message = s_.message_;
  }

  // While paused, reads the input until the player goes on (or ends the flight).
  Ask wait_while_paused(const StepSnapshot& snap) {
    Ask ask;
    while (hud_.paused) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
      const bool redraw = poll(ask);
      if (ask.kind != Ask::Kind::kFlyOn) return ask;
      // The camera stands still while paused, so a mouse moved meanwhile turns nothing.
      s_.held_.mouse_yaw_rad = 0.0;
      s_.held_.mouse_pitch_rad = 0.0;
      if (redraw || !hud_.paused) draw(snap, false);
      if (!hud_.paused) {  // the clock starts again from here
        wall_base_ = Clock::now();
        t_base_ = snap.t_s;
        last_end_ = wall_base_;
        rate_.clear();
      }
    }
    return ask;
  }

  // Polls the front end once; sets `ask` when a command ends the flight (the events after it are
  // not looked at). True if the picture must be drawn again.
  bool poll(Ask& ask) {
    events_.clear();
    s_.frontend_.poll(s_.session_steps_, events_, s_.held_);
    bool redraw = false;
    for (const PlayEvent& e : events_) {
      switch (e.command) {
        case PlayCommand::kQuit:
          ask = {Ask::Kind::kQuit, 0};
          return redraw;
        case PlayCommand::kRestart:
          ask = {Ask::Kind::kFly, s_.current_};
          return redraw;
        case PlayCommand::kNextStrategy:
          ask = {Ask::Kind::kFly, (s_.current_ + 1) % s_.strategies_.size()};
          return redraw;
        case PlayCommand::kChooseStrategy:
          if (e.strategy >= 0 && static_cast<std::size_t>(e.strategy) < s_.strategies_.size()) {
            ask = {Ask::Kind::kFly, static_cast<std::size_t>(e.strategy)};
            return redraw;
          }
          break;
        case PlayCommand::kPause:
          hud_.paused = !hud_.paused;
          redraw = true;
          break;
        case PlayCommand::kOverlays:
          s_.overlays_ = !s_.overlays_;
          redraw = true;
          break;
        case PlayCommand::kScreenshot:
          screenshot_ = true;
          redraw = true;
          break;
      }
    }
    return redraw;
  }

  void draw(const StepSnapshot& snap, bool timed) {
    const auto t0 = Clock::now();
    Image image = (s_.overlays_ ? with_ : without_).render(snap);
    draw_hud(image, hud_);
    const auto t1 = Clock::now();
    s_.frontend_.present(image);
    const auto t2 = Clock::now();
    if (screenshot_) {
      screenshot_ = false;
      const std::string path = numbered_png(s_.options_.screenshot_folder);
      write_png(path, image);
      if (s_.on_message) s_.on_message("wrote " + path);
    }
    if (!timed) return;
    FrameTimes& t = s_.times_;
    t.physics_ms.push_back(physics_ms_);
    t.strategy_ms.push_back(strategy_ms_);
    t.draw_ms.push_back(ms_between(t0, t1));
    t.present_ms.push_back(ms_between(t1, t2));
    t.frame_ms.push_back(ms_between(last_end_, t2));
    physics_ms_ = 0.0;
    strategy_ms_ = 0.0;
    last_drawn_t_s_ = snap.t_s;
    char text[160];
    std::snprintf(text, sizeof text, "flight %d, %s, %.1f s", s_.flights_ + 1, strategy_.c_str(),
                  snap.t_s);
    if (status_ != text) {
      status_ = text;
      s_.frontend_.show_status(status_);
    }
  }

  // Waits until the clock reaches simulated time; when it is already past, simulated time gives
  // way (it is never caught up by running faster), and the rate over the last second says so.
  void pace(double t_s) {
    if (s_.frontend_.paced()) {
      const auto target = wall_base_ + std::chrono::duration_cast<Clock::duration>(
                                           std::chrono::duration<double>(t_s - t_base_));
      const auto now = Clock::now();
      if (now < target) {
        std::this_thread::sleep_until(target);
      } else {
        wall_base_ = now;
        t_base_ = t_s;
      }
    }
    last_end_ = Clock::now();
    rate_.push_back({last_end_, t_s});
    while (rate_.size() > 2 &&
           std::chrono::duration<double>(last_end_ - rate_.front().first).count() > kRateWindowS) {
      rate_.pop_front();
    }
    const double wall_s = std::chrono::duration<double>(last_end_ - rate_.front().first).count();
    hud_.time_rate = wall_s > 0.25 * kRateWindowS ? (t_s - rate_.front().second) / wall_s : 1.0;
  }

  PlaySession& s_;
  const NearPlaneMetric& near_;
  FrameRenderer& with_;
  FrameRenderer& without_;
  std::string strategy_;
  HudState hud_;
  std::vector<PlayEvent> events_;
  bool screenshot_ = false;
  std::string status_;       // as last shown by the front end
  double physics_ms_ = 0.0;  // the steps' since the last timed frame
  double strategy_ms_ = 0.0;
  double last_drawn_t_s_ = 0.0;
  Clock::time_point last_end_;
  Clock::time_point wall_base_;
  double t_base_ = 0.0;
  std::deque<std::pair<Clock::time_point, double>> rate_;
};

PlaySession::PlaySession(const Scene& scene, PlayOptions options, PlayFrontend& frontend)
    : flight_scene_(scene_as_flown(scene)),
      options_(std::move(options)),
      frontend_(frontend),
      strategies_(strategy_names()),
      controls_(scene.camera, make_camera_motion(scene)->pose_at(0.0)) {
  for (const std::string& name : strategies_) validate_strategy_settings(name, flight_scene_);
  current_ = strategies_.size();
  for (std::size_t i = 0; i < strategies_.size(); ++i) {
    if (strategies_[i] == options_.strategy) current_ = i;
  }
  if (current_ == strategies_.size()) {
    validate_strategy_settings(options_.strategy, flight_scene_);  // throws
  }
}

void PlaySession::run() {
  FrameStyle plain = options_.style;
  plain.overlays = {};
  FrameRenderer with_overlays(flight_scene_, options_.style);
  FrameRenderer without(flight_scene_, plain);
  const double dt = flight_scene_.sim.dt_s;
  for (;;) {
    const std::string name = strategies_[current_];
    const std::unique_ptr<SceneStrategy> strategy = make_strategy(name, flight_scene_);
    // The camera goes on from where the last flight left it. The run, as it is built, asks for
    // the velocity over its first step, the sample at dt under what is held then.
    SteeredCamera camera(flight_scene_.camera, dt, controls_.sample(0.0));
    camera.steer(controls_.step(held_, camera.next_t_s(), dt));
    NearPlaneMetric near;
    RunObserver* const observers[] = {&near};
    Run run(flight_scene_, *strategy, camera, observers);
    Flight flight(*this, near, name, with_overlays, without);
    const Ask end = flight.fly(run, camera);
    run.finish();

    const StepSnapshot& last = run.state();
    RunSummary counts;
    near.fill(counts);
    FlightReport report;
    report.flight = ++flights_;
    report.strategy = name;
    report.steps = last.step;
    report.t_s = last.t_s;
    report.near_fragments = counts.intersections.near_fragments;
    report.camera_hits = counts.intersections.camera_hit_fragments;
    if (options_.record_flights && report.steps > 0) {
      report.recorded = record_paths(options_.record, ++recorded_, options_.record_folder);
      write_flight(*report.recorded, flight_scene_, name, camera.samples(), report.steps);
      message_ = "recorded " + report.recorded->track_csv + "  replay: fragsim compare --scene " +
                 report.recorded->scene_ini;
    }
    if (on_flight) on_flight(report);
    if (end.kind == Ask::Kind::kQuit) return;
    current_ = end.strategy;
  }
}

}  // namespace fragsim
