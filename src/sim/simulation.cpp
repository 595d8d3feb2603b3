#include "sim/simulation.hpp"

#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <utility>

#include "sim/camera_motion.hpp"
#include "sim/explosion.hpp"
#include "sim/world.hpp"

namespace fragsim {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// The test-only signal (arm_test_signal_from_environment); plain data, copied into workers by fork.
struct TestSignal {
  int signo = 0;  // 0: not armed
  long at_step = 0;
  long steps = 0;
  pid_t target = 0;  // 0: the process that counts the step
};
TestSignal g_test_signal;

void count_test_step() {
  if (g_test_signal.signo != 0 && ++g_test_signal.steps == g_test_signal.at_step) {
    ::kill(g_test_signal.target != 0 ? g_test_signal.target : ::getpid(), g_test_signal.signo);
  }
}

}  // namespace

void arm_test_signal_from_environment() {
  const char* step = std::getenv("FRAGSIM_TEST_RAISE_AT_STEP");
  const char* name = std::getenv("FRAGSIM_TEST_RAISE_SIGNAL");
  if (!step || !name) return;
  const long at = std::strtol(step, nullptr, 10);
  int signo = 0;
  for (const auto& [n, s] : {std::pair{"INT", SIGINT}, std::pair{"TERM", SIGTERM},
                             std::pair{"HUP", SIGHUP}, std::pair{"KILL", SIGKILL}}) {
    if (std::strcmp(name, n) == 0) signo = s;
  }
  if (at < 1 || signo == 0) return;
  const char* in = std::getenv("FRAGSIM_TEST_RAISE_IN");
  const bool self = in && std::strcmp(in, "self") == 0;
  g_test_signal = {signo, at, 0, self ? 0 : ::getpid()};
}

int Scene::step_count() const {
  // The last step ends at or just past duration_s; the 1e-9 keeps 3 s / (1/60 s) at 180.
  return static_cast<int>(std::ceil(sim.duration_s / sim.dt_s - 1e-9));
}

RunTotals simulate(const Scene& scene, Strategy& strategy,
                   std::span<RunObserver* const> observers) {
  return simulate(scene, strategy, *make_camera_motion(scene), observers);
}

RunTotals simulate(const Scene& scene, Strategy& strategy, const CameraMotion& path,
                   std::span<RunObserver* const> observers) {
  const auto run_start = Clock::now();
  const long messages_before = World::ode_messages();
  const CameraLimits limits = declared_limits(scene.camera);
  World world(scene, strategy.needs(), explode(scene, path));
  std::vector<FragmentState> states = world.init_states();
  strategy.reset(world.fragment_count());

  const double dt = scene.sim.dt_s;
  const int steps = scene.step_count();
  const Eigen::Vector3d body_half = 0.5 * scene.camera.body_size_m;

  StepSnapshot snap;
  snap.step = 0;
  snap.t_s = 0.0;
  snap.camera = path.pose_at(0.0);
  snap.camera_velocity_mps = path.velocity_at(0.0);
  snap.camera_body_half_m = body_half;
  snap.fragments = states;
  const RunInfo info{&scene, strategy.name(), world.fragment_count(), steps, dt};
  for (RunObserver* o : observers) o->begin(info, snap);

  RunTotals totals;
  StepOutput out;
  std::vector<Eigen::Vector3d> last_finite(states.size());
  for (std::size_t i = 0; i < states.size(); ++i) last_finite[i] = states[i].position_m;
  std::vector<char> frozen(states.size(), 0);
  for (int k = 0; k < steps; ++k) {
    const double t = k * dt;
    StepContext ctx;
    ctx.step = k;
    ctx.t_s = t;
    ctx.dt_s = dt;
    // No end_time_s: the scene's duration is where fragsim stops measuring, which a strategy in a
    // game could not know (ctx.end_time_s stays +infinity).
    ctx.camera = path.pose_at(t);
    ctx.camera_velocity_mps = path.velocity_at(t);
    ctx.camera_max_speed_mps = limits.max_speed_mps;
    ctx.camera_max_accel_mps2 = limits.max_accel_mps2;
    ctx.camera_max_turn_radps = limits.max_turn_radps;
    ctx.camera_body_half_m = body_half;
    ctx.gravity_mps2 = scene.sim.gravity_mps2;
    ctx.ground_height_m =
        scene.ground.enabled ? scene.ground.height_m : -std::numeric_limits<double>::infinity();
    ctx.fragments = states;

    out.clear();
    const auto strategy_start = Clock::now();
    strategy.step(ctx, out);
    const double strategy_s = seconds_since(strategy_start);

    const auto physics_start = Clock::now();
    world.set_camera(ctx.camera, ctx.camera_velocity_mps);
    world.add_forces(out.forces);
    world.step(dt);
    world.read(states);
    const double physics_s = seconds_since(physics_start);
    // Always-on state check (MuJoCo's habit): a non-finite fragment is counted and frozen where
    // it last was finite, so no NaN reaches a strategy, a metric or a file.
    for (std::size_t i = 0; i < states.size(); ++i) {
      FragmentState& f = states[i];
      if (f.position_m.allFinite() && f.velocity_mps.allFinite() && f.rotation.allFinite()) {
        last_finite[i] = f.position_m;
        continue;
      }
      if (!frozen[i]) {
        frozen[i] = 1;
        ++totals.nonfinite_fragments;
      }
      f.position_m = last_finite[i];
      f.velocity_mps.setZero();
      f.rotation.setIdentity();
    }

    totals.physics_s += physics_s;
    totals.strategy_s += strategy_s;
    ++totals.steps;

    const double t_next = (k + 1) * dt;
    snap.step = k + 1;
    snap.t_s = t_next;
    snap.camera = path.pose_at(t_next);
    if (out.near_m) snap.camera.near_m = *out.near_m;
    snap.camera_velocity_mps = path.velocity_at(t_next);
    snap.fragments = states;
    snap.forces = out.forces;
    snap.candidates = out.activity.candidates;
    snap.capped = out.activity.capped;
    snap.guarded = out.activity.guarded;
    snap.deferred = out.activity.deferred;
    snap.opacity = out.opacity;
    snap.camera_hits = world.camera_hits();
    snap.wall_contacts = world.wall_contacts();
    snap.physics_s = physics_s;
    snap.strategy_s = strategy_s;
    for (RunObserver* o : observers) o->observe(snap);
    count_test_step();
  }
  for (RunObserver* o : observers) o->end();
  totals.wall_s = seconds_since(run_start);
  totals.ode_messages = World::ode_messages() - messages_before;
  return totals;
}

}  // namespace fragsim
