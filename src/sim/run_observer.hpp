#pragma once
// Observers watch a run. After every step they get a read-only snapshot and can never change the
// simulation. Metrics, recorders and progress reports are observers.

#include <span>
#include <string>
#include <vector>

#include "control/geometry/camera_pose.hpp"
#include "control/geometry/fragment_state.hpp"

namespace fragsim {

struct Scene;

// The state after a step (or, for step 0, right after the explosion).
struct StepSnapshot {
  int step = 0;  // 0 = the explosion; step k is the state at t = k dt
  double t_s = 0.0;
  CameraPose camera;  // as rendered at t_s, with the near distance in force then
  Eigen::Vector3d camera_velocity_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d camera_body_half_m = Eigen::Vector3d::Zero();
  std::span<const FragmentState> fragments;
  // What the strategy did in the step that led here (empty for step 0).
  std::span<const AppliedForce> forces;
  std::span<const int> candidates;
  std::span<const int> capped;  // fragments whose force the cap reduced
  int guarded = 0;
  int deferred = 0;  // fragments a per-step budget left unsolved
  // Each fragment's opacity in this frame (fade). Empty means all opaque (every other strategy, and
  // step 0, drawn before any strategy spoke).
  std::span<const float> opacity;
  // What the physics saw in that step.
  std::span<const int> camera_hits;  // fragments that touched the camera's sensor volume
  int wall_contacts = 0;
  double physics_s = 0.0;   // wall time of the physics step
  double strategy_s = 0.0;  // wall time of the strategy's step
};

struct RunInfo {
  const Scene* scene = nullptr;
  std::string strategy;
  int fragment_count = 0;
  int step_count = 0;
  double dt_s = 0.0;
};

class RunObserver {
 public:
  virtual ~RunObserver() = default;
  virtual void begin(const RunInfo& info, const StepSnapshot& initial) = 0;
  virtual void observe(const StepSnapshot& snap) = 0;
  virtual void end() {}
};

}  // namespace fragsim
