#pragma once
// The controller's strategy interface, which stands between the explosion and the camera. A
// strategy sees the world through StepContext (read-only) and answers forces through StepOutput;
// the controller (or the tool's run) applies them. Parameters are fixed at construction; reset()
// clears the run state so a rerun is reproducible.

#include <limits>
#include <span>
#include <string>
#include <vector>

#include "control/geometry/camera_pose.hpp"
#include "control/geometry/fragment_state.hpp"
#include "control/memory/memory_resource.hpp"
#include "control/strategies/parallel_for.hpp"

namespace fragsim {

// A camera bound not declared (StepContext::camera_max_accel_mps2, _turn_degps). Any negative
// number reads so, and this one is what the tool and the C API's FRAGSIM_UNDECLARED pass.
inline constexpr double kUndeclaredBound = -1.0;

// Everything a strategy may know at the start of a step, the present, never the camera's future.
struct StepContext {
  int step = 0;      // index of the step about to be taken
  double t_s = 0.0;  // time at the start of the step; 0 is the explosion
  double dt_s = 0.0;
  // When the shot ends, if the caller knows (a cut-scene), an extra cap on every look-ahead, else
  // +infinity. The tool passes +infinity too, as its scene duration is where measuring stops, not
  // something a strategy in a game could know. Look-ahead comes from the physics (time to the
  // ground or to the camera's height) and each strategy's horizon_cap_s.
  double end_time_s = std::numeric_limits<double>::infinity();
  CameraPose camera;  // as rendered now (scene near distance)
  Eigen::Vector3d camera_velocity_mps = Eigen::Vector3d::Zero();  // over the step being taken
  double camera_max_speed_mps = 0.0;                              // V_c
  // The camera's declared limits beyond V_c. Each is kUndeclaredBound where the scene declares none
  // (a scripted path or a replayed track may start, stop and turn at once, so it promises nothing),
  // +infinity where it declares that there is no bound (a player with instant turns), else the
  // bound (0 included, a camera that cannot turn). A strategy that assumes a bound the scene does
  // not declare says so in its own parameters.
  double camera_max_accel_mps2 = kUndeclaredBound;
  double camera_max_turn_degps = kUndeclaredBound;
  Eigen::Vector3d camera_body_half_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d gravity_mps2 = Eigen::Vector3d::Zero();
  double ground_height_m = -std::numeric_limits<double>::infinity();  // -infinity for no ground
  std::span<const FragmentState> fragments;
  // Where per-fragment work may run, the game's workers, or nullptr for the calling thread. It
  // changes how fast a step is, never what it answers.
  const ParallelFor* parallel = nullptr;
};

// What a strategy did in a step besides its effects, for the report (RunSummary's strategy
// activity) and the C API's stats. Nothing here changes the world.
//
// The containers here and in the strategies take a MemoryResource. The tool runs them on the
// default one (operator new), the controller library on the game's allocator hook.
struct StepActivity {
  explicit StepActivity(MemoryResource* mem = default_memory_resource())
      : candidates(mem), capped(mem) {}
  ResourceVector<int> candidates;  // fragments the strategy considers threatening (edge)
  ResourceVector<int> capped;      // fragments whose force the acceleration cap reduced
  int guarded = 0;                 // singular spots (t_C - t -> 0, |P_pc| -> 0) guarded
  int deferred = 0;                // fragments a per-step budget left unsolved (edge-min)
  // Fragments a cheap test settled before any exact solve (edge-min's box rejection).
  int rejected_cheaply = 0;

  void reserve(std::size_t n) {
    candidates.reserve(n);
    capped.reserve(n);
  }
  void clear() {
    candidates.clear();
    capped.clear();
    guarded = 0;
    deferred = 0;
    rejected_cheaply = 0;
  }
};

// A strategy's answer for one step, the forces the physics applies and the strategy's activity for
// the report and the C API's stats.
struct StepOutput {
  explicit StepOutput(MemoryResource* mem = default_memory_resource())
      : forces(mem), activity(mem) {}
  ResourceVector<AppliedForce> forces;  // at most one entry per fragment
  StepActivity activity;

  // Room for one force per fragment, so a step within it does not allocate.
  void reserve(std::size_t n) {
    forces.reserve(n);
    activity.reserve(n);
  }
  void clear() {
    forces.clear();
    activity.clear();
  }
};

class Strategy {
 public:
  virtual ~Strategy() = default;
  virtual std::string name() const = 0;
  // Called once, right after construction and before reserve(), by a caller that runs steps with a
  // ParallelFor of that many workers (StepContext::parallel), to keep a work space per worker. May
  // throw std::bad_alloc.
  virtual void set_worker_count(int workers) { (void)workers; }
  // Called before the first step of every run.
  virtual void reset(int fragment_count) = 0;
  // Grows the work space for steps of up to fragment_count fragments, changing nothing of the run.
  // The controller library calls it before a step changes any state, so an allocation that fails
  // fails there and leaves the controller as it was.
  virtual void reserve(int fragment_count) { (void)fragment_count; }
  // Called once per step, before the physics step; `out` arrives cleared.
  virtual void step(const StepContext& ctx, StepOutput& out) = 0;
};

}  // namespace fragsim
