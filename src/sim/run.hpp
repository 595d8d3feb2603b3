#pragma once
// One run you can step: a scene, a strategy, the camera's motion and the observers that watch it.
// This is the only place where the three meet. Each step() asks the strategy first, then steps the
// physics, then shows the observers the state it left. Between steps the state can be read (the
// same snapshot the observers got), so a caller can draw it, steer the camera or stop when it
// likes; simulate() steps a run to its end, `fragsim play` steps one while a person flies.

#include <chrono>
#include <memory>
#include <span>
#include <vector>

#include "sim/camera_motion.hpp"
#include "sim/run_observer.hpp"
#include "sim/scene.hpp"
#include "sim/world.hpp"
#include "strategies/scene_strategy.hpp"

namespace fragsim {

struct RunTotals {
  int steps = 0;
  double physics_s = 0.0;
  double strategy_s = 0.0;
  double wall_s = 0.0;          // the whole run, observers included
  long ode_messages = 0;        // warnings ODE printed during the run
  int nonfinite_fragments = 0;  // fragments whose state became NaN or infinite (then frozen)
};

class Run {
 public:
  // Explodes the scene, builds its world, resets the strategy and shows the observers the state
  // at t = 0 (their begin()). The scene, the strategy, the camera and the observers (with the
  // array `observers` views) must outlive the run. The camera's motion is made from camera.mode.
  Run(const Scene& scene, SceneStrategy& strategy, std::span<RunObserver* const> observers = {});
  // The same with the camera's motion given by the caller (a camera steered live, src/play). Step k
  // asks for its pose and velocity at k dt, then, as it ends, at (k + 1) dt, and nothing later. A
  // track's velocity over [t, t + dt) needs the sample after it, so before step k a steered camera
  // must have samples up to (k + 2) dt, and before the run is built up to dt.
  Run(const Scene& scene, SceneStrategy& strategy, const CameraMotion& camera,
      std::span<RunObserver* const> observers = {});
  ~Run();
  // The snapshot points into the run's own buffers.
  Run(const Run&) = delete;
  Run& operator=(const Run&) = delete;

  // One step of dt. The strategy answers, the physics steps, a fragment whose state became
  // non-finite is frozen where it last was finite, and the observers see the result. Throws
  // std::logic_error when done() or after finish().
  void step();
  // True once the scene's step count is reached.
  bool done() const { return totals_.steps >= step_count_; }
  int step_count() const { return step_count_; }

  // The current state, after the last step, or right after the explosion before the first (step 0),
  // as the observers saw it last; valid until the next step.
  const StepSnapshot& state() const { return snap_; }
  // What the strategy will be told at the next step (the camera's present, never its future).
  StepContext next_context() const;
  // The totals so far (wall time and ODE messages up to this point).
  RunTotals totals() const;

  // Ends the run, after its last step or before (a flight the player ends), with the observers'
  // end(), then the totals. A run destroyed without finish() never calls end(). Further calls
  // return the same totals.
  RunTotals finish();

 private:
  using Clock = std::chrono::steady_clock;

  Run(const Scene& scene, SceneStrategy& strategy, std::unique_ptr<CameraMotion> own_camera,
      const CameraMotion* camera, std::span<RunObserver* const> observers);

  const Scene& scene_;
  SceneStrategy& strategy_;
  std::unique_ptr<CameraMotion> own_camera_;  // when made from camera.mode
  const CameraMotion& camera_;
  std::span<RunObserver* const> observers_;
  const Clock::time_point start_;
  const long messages_before_;
  const CameraLimits limits_;
  const Eigen::Vector3d body_half_m_;
  World world_;
  std::vector<FragmentState> states_;
  std::vector<Eigen::Vector3d> last_finite_;
  std::vector<char> frozen_;
  SceneStepOutput out_;
  StepSnapshot snap_;
  const int step_count_;
  RunTotals totals_;
  bool finished_ = false;
};

}  // namespace fragsim
