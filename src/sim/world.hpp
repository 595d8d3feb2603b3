#pragma once
// The physics world, the only place that knows about ODE. Fragments are dynamic boxes or convex
// pieces (FragmentSpawn::shape), the ground a plane, the camera a kinematic body whose box is a
// sensor (touching it records a hit, nothing bounces), and, when a strategy asks for one, a
// kinematic wall carried in front of the camera.

#include <memory>
#include <span>
#include <string>
#include <vector>

#include "control/geometry/camera_pose.hpp"
#include "control/geometry/fragment_state.hpp"
#include "sim/explosion.hpp"
#include "sim/scene.hpp"
#include "strategies/scene_strategy.hpp"

namespace fragsim {

// What ODE does with a fragment this step.
enum class FragmentActivity {
  kAwake,   // stepped and collided
  kAsleep,  // at rest and disabled by ODE's auto-disable, so not stepped; its geom still collides
  // At rest, out of view and away from the camera, so neither stepped nor collided (with fragment
  // collisions its geom stays, so that other fragments still meet it and wake it).
  kCulled,
};

class World {
 public:
  World(const Scene& scene, const WorldNeeds& needs, const std::vector<FragmentSpawn>& spawns);
  ~World();
  World(const World&) = delete;
  World& operator=(const World&) = delete;

  int fragment_count() const;
  // Positions, velocities, rotations and last-step contact flags of every fragment; `out` must
  // already hold the fragments' constant data (see init_states).
  void read(std::vector<FragmentState>& out) const;
  // Constant data (extents, mass, radius) plus the current state.
  std::vector<FragmentState> init_states() const;

  // Places the camera (and the wall, if any) for the coming step.
  void set_camera(const CameraPose& pose, const Eigen::Vector3d& velocity_mps);
  // Wakes a sleeping or culled fragment before pushing it.
  void add_forces(std::span<const AppliedForce> forces);
  // Culling (simulation.cull_resting), collision detection and one ODE step.
  void step(double dt_s);

  FragmentActivity activity(int fragment) const;
  // Fragments ODE steps (neither asleep nor culled).
  int awake_count() const;
  int culled_count() const;

  // Fragments that touched the camera's sensor volume in the last step (each once, ascending).
  const std::vector<int>& camera_hits() const;
  // Contact points between fragments and the wall in the last step.
  int wall_contacts() const;

  // Warnings ODE has printed in this process so far (its message hook has no context), but for
  // the exact solver's LCP failures that step() redid.
  static long ode_messages();
  // Exact steps redone with the iterative solver after ODE's LCP failed, in this process so far.
  static long exact_step_retries();

  // The version string of the ODE library, for reports.
  static std::string ode_version();

 private:
  friend struct WorldProbe;  // sim/world_probe.hpp, for tests
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace fragsim
