#pragma once
// Small hand-made scenes and cameras for the tests: one fragment fired along a known line at a
// still camera, a square 90-degree camera, a player camera, a three-point path, a standing start
// pose, a cube fragment's state, and a recorder of every step.

#include <cmath>
#include <string>
#include <vector>

#include "control/geometry/camera_pose.hpp"
#include "experiments/evaluation.hpp"
#include "sim/run_observer.hpp"
#include "sim/scene.hpp"

namespace fragsim::test {

// A cube of half size `half_m` and 1 kg at `p`, axis-aligned, at rest: what a metric or a
// strategy sees of one fragment.
inline FragmentState box_at(const Eigen::Vector3d& p, double half_m) {
  FragmentState f;
  f.position_m = p;
  f.half_extents_m = Eigen::Vector3d::Constant(half_m);
  f.mass_kg = 1.0;
  f.radius_m = half_m * std::sqrt(3.0);
  return f;
}

// The default scene with a still camera at (0, 1.6, 0) looking down -z (right = +x, up = +y);
// the ground on at y = 0.
inline Scene still_camera_scene(const std::string& name) {
  Scene s;
  s.name = name;
  s.camera.waypoints_m = {{0.0, 1.6, 0.0}};
  s.camera.look_at_m = {{0.0, 1.6, -10.0}};
  s.camera.speed_mps = 0.0;
  return s;
}

// A still camera at (0, 1.6, 0) looking down -z (right = +x, up = +y), and one 0.1 m box at
// `start_m` moving at `speed_mps` along +z (toward the camera) with no gravity, no spin, no ground.
inline Scene single_fragment(const Eigen::Vector3d& start_m, double speed_mps = 10.0) {
  Scene s;
  s.name = "single";
  s.sim.duration_s = 1.5;
  s.sim.gravity_mps2 = Eigen::Vector3d::Zero();
  s.object.centre_m = start_m;
  s.object.size_m = 0.1;
  s.object.splits = 1;
  s.object.gap = 0.0;
  // The blast sits 1 m behind the fragment, so its radial push is exactly +z.
  s.explosion.offset_m = {0.0, 0.0, -1.0};
  s.explosion.speed_mps = speed_mps;
  s.explosion.jitter = 0.0;
  s.explosion.spin_radps = 0.0;
  s.explosion.toward_camera_mps = 0.0;
  s.ground.enabled = false;
  s.camera.waypoints_m = {{0.0, 1.6, 0.0}};
  s.camera.look_at_m = {{0.0, 1.6, -10.0}};
  s.camera.speed_mps = 0.0;
  s.camera.max_speed_mps = 1.0;
  return s;
}

// Keeps a copy of every snapshot's fragments, forces, candidates and camera near distance.
class Recorder final : public RunObserver {
 public:
  struct Step {
    std::vector<FragmentState> fragments;
    std::vector<AppliedForce> forces;
    std::vector<int> candidates;
    std::vector<int> camera_hits;
    double near_m = 0.0;
  };
  std::vector<Step> steps;  // steps[0] is the explosion

  void begin(const RunInfo&, const StepSnapshot& s) override {
    steps.clear();
    keep(s);
  }
  void observe(const StepSnapshot& s) override { keep(s); }

 private:
  void keep(const StepSnapshot& s) {
    steps.push_back({{s.fragments.begin(), s.fragments.end()},
                     {s.forces.begin(), s.forces.end()},
                     {s.candidates.begin(), s.candidates.end()},
                     {s.camera_hits.begin(), s.camera_hits.end()},
                     s.camera.near_m});
  }
};

// A 90-degree, square camera with its eye at the origin, right +x, up +y, forward -z: a point at
// depth z and lateral offset x has NDC x / z, so expected screen positions are worked by hand.
inline CameraPose square_camera(double near_m = 0.1) {
  CameraPose cam;
  cam.fovy_deg = 90.0;
  cam.aspect = 1.0;
  cam.near_m = near_m;
  return cam;
}

// One evaluated run of `strategy` on `scene`: every step as recorded, and the run's summary.
struct RecordedRun {
  Recorder rec;
  RunSummary summary;
};

inline RecordedRun run_recorded(const Scene& scene, const std::string& strategy) {
  RecordedRun o;
  o.summary = evaluate(scene, strategy, {nullptr, nullptr, false, {&o.rec}}).summary;
  return o;
}

// A player camera at (0, 1.6, 0) facing an object 10 m down -z, at most 4 m/s.
inline Scene player_scene() {
  Scene s;
  s.camera.mode = CameraMode::kPlayer;
  s.camera.waypoints_m = {{0.0, 1.6, 0.0}};
  s.camera.look_at_m = {{0.0, 1.2, -10.0}};
  s.camera.max_speed_mps = 4.0;
  s.object.centre_m = {0.0, 1.2, -10.0};
  return s;
}

// A path through three waypoints (2 m straight, then 2.5 m to the side) at 2 m/s, bound 3 m/s.
inline CameraDef three_point_path() {
  CameraDef c;
  c.waypoints_m = {{0.0, 1.6, 0.0}, {0.0, 1.6, -2.0}, {1.5, 1.6, -4.0}};
  c.look_at_m = {{0.0, 1.2, -10.0}};
  c.speed_mps = 2.0;
  c.max_speed_mps = 3.0;
  return c;
}

// Standing at (0, 1.6, 0), looking down -z: where a flown camera starts.
inline CameraPose start_pose() {
  CameraPose p;
  p.eye_m = {0.0, 1.6, 0.0};
  return p;
}

}  // namespace fragsim::test
