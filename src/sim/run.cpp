#include "sim/run.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "sim/explosion.hpp"

namespace fragsim {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

}  // namespace

Run::Run(const Scene& scene, SceneStrategy& strategy, std::span<RunObserver* const> observers)
    : Run(scene, strategy, make_camera_motion(scene), nullptr, observers) {}

Run::Run(const Scene& scene, SceneStrategy& strategy, const CameraMotion& camera,
         std::span<RunObserver* const> observers)
    : Run(scene, strategy, nullptr, &camera, observers) {}

Run::Run(const Scene& scene, SceneStrategy& strategy, std::unique_ptr<CameraMotion> own_camera,
         const CameraMotion* camera, std::span<RunObserver* const> observers)
    : scene_(scene),
      strategy_(strategy),
      own_camera_(std::move(own_camera)),
      camera_(own_camera_ ? *own_camera_ : *camera),
      observers_(observers),
      start_(Clock::now()),
      messages_before_(World::ode_messages()),
      limits_(declared_limits(scene.camera)),
      body_half_m_(0.5 * scene.camera.body_size_m),
      world_(scene, strategy.needs(), explode(scene, camera_)),
      states_(world_.init_states()),
      step_count_(scene.step_count()) {
  strategy_.reset(world_.fragment_count());

  last_finite_.resize(states_.size());
  for (std::size_t i = 0; i < states_.size(); ++i) last_finite_[i] = states_[i].position_m;
  frozen_.assign(states_.size(), 0);

  snap_.step = 0;
  snap_.t_s = 0.0;
  snap_.camera = camera_.pose_at(0.0);
  snap_.camera_velocity_mps = camera_.velocity_at(0.0);
  snap_.camera_body_half_m = body_half_m_;
  snap_.fragments = states_;
  const RunInfo info{&scene_, strategy_.name(), world_.fragment_count(), step_count_,
                     scene_.sim.dt_s};
  for (RunObserver* o : observers_) o->begin(info, snap_);
}

Run::~Run() = default;

StepContext Run::next_context() const {
  const int k = totals_.steps;
  const double t = k * scene_.sim.dt_s;
  StepContext ctx;
  ctx.step = k;
  ctx.t_s = t;
  ctx.dt_s = scene_.sim.dt_s;
  // No end_time_s, because the scene's duration is where fragsim stops measuring, which a strategy
  // in a game could not know (ctx.end_time_s stays +infinity).
  ctx.camera = camera_.pose_at(t);
  ctx.camera_velocity_mps = camera_.velocity_at(t);
  ctx.camera_max_speed_mps = limits_.max_speed_mps;
  ctx.camera_max_accel_mps2 = limits_.max_accel_mps2;
  ctx.camera_max_turn_degps = limits_.max_turn_degps;
  ctx.camera_body_half_m = body_half_m_;
  ctx.gravity_mps2 = scene_.sim.gravity_mps2;
  ctx.ground_height_m =
      scene_.ground.enabled ? scene_.ground.height_m : -std::numeric_limits<double>::infinity();
  ctx.fragments = states_;
  return ctx;
}

void Run::step() {
  if (done() || finished_) throw std::logic_error("Run::step: the run has ended");
  const double dt = scene_.sim.dt_s;
  const StepContext ctx = next_context();

  out_.clear();
  const auto strategy_start = Clock::now();
  strategy_.step(ctx, out_);
  const double strategy_s = seconds_since(strategy_start);

  const auto physics_start = Clock::now();
  world_.set_camera(ctx.camera, ctx.camera_velocity_mps);
  world_.add_forces(out_.forces);
  world_.step(dt);
  world_.read(states_);
  const double physics_s = seconds_since(physics_start);
  // An always-on state check (MuJoCo's habit) counts a non-finite fragment and freezes it where it
  // last was finite, so no NaN reaches a strategy, a metric or a file.
  for (std::size_t i = 0; i < states_.size(); ++i) {
    FragmentState& f = states_[i];
    if (f.position_m.allFinite() && f.velocity_mps.allFinite() && f.rotation.allFinite()) {
      last_finite_[i] = f.position_m;
      continue;
    }
    if (!frozen_[i]) {
      frozen_[i] = 1;
      ++totals_.nonfinite_fragments;
    }
    f.position_m = last_finite_[i];
    f.velocity_mps.setZero();
    f.rotation.setIdentity();
  }

  totals_.physics_s += physics_s;
  totals_.strategy_s += strategy_s;
  ++totals_.steps;

  const double t_next = totals_.steps * dt;
  snap_.step = totals_.steps;
  snap_.t_s = t_next;
  snap_.camera = camera_.pose_at(t_next);
  if (out_.near_m) snap_.camera.near_m = *out_.near_m;
  snap_.camera_velocity_mps = camera_.velocity_at(t_next);
  snap_.fragments = states_;
  snap_.forces = out_.forces;
  snap_.candidates = out_.activity.candidates;
  snap_.capped = out_.activity.capped;
  snap_.guarded = out_.activity.guarded;
  snap_.deferred = out_.activity.deferred;
  snap_.opacity = out_.opacity;
  snap_.camera_hits = world_.camera_hits();
  snap_.wall_contacts = world_.wall_contacts();
  snap_.physics_s = physics_s;
  snap_.strategy_s = strategy_s;
  for (RunObserver* o : observers_) o->observe(snap_);
}

RunTotals Run::totals() const {
  if (finished_) return totals_;
  RunTotals t = totals_;
  t.wall_s = seconds_since(start_);
  t.ode_messages = World::ode_messages() - messages_before_;
  return t;
}

RunTotals Run::finish() {
  if (finished_) return totals_;
  for (RunObserver* o : observers_) o->end();
  totals_ = totals();
  finished_ = true;
  return totals_;
}

}  // namespace fragsim
