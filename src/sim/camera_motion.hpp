#pragma once
// Where the camera is at every instant, whichever way its motion is given (camera.mode), as a
// scripted path, a replayed track or a seeded player. The simulation asks it for the pose and the
// velocity of each step; strategies only ever see those of the present step.

#include <memory>

#include "control/geometry/camera_pose.hpp"
#include "control/strategies/strategy.hpp"
#include "sim/scene.hpp"

namespace fragsim {

class CameraMotion {
 public:
  virtual ~CameraMotion() = default;
  virtual Eigen::Vector3d eye_at(double t_s) const = 0;
  // The velocity over the step that starts at t_s (right-continuous at a path's corners and at a
  // track's samples).
  virtual Eigen::Vector3d velocity_at(double t_s) const = 0;
  // The pose at t_s with the scene's frustum.
  virtual CameraPose pose_at(double t_s) const = 0;
};

// The camera's limits as the scene declares them, for the strategies (StepContext's rule). V_c
// always; acceleration and turn rate only for a player (its acceleration may be +infinity, for
// instant turns); kUndeclaredBound for a path or a track, which may start, stop and turn at once.
// They reach a strategy as StepContext's camera_max_* (a game's as fragsim_camera_def's max_*).
struct CameraLimits {
  double max_speed_mps = 0.0;
  double max_accel_mps2 = kUndeclaredBound;
  double max_turn_degps = kUndeclaredBound;
};
CameraLimits declared_limits(const CameraDef& camera);

// The motion camera.mode asks for (a track's samples are already in camera.track_samples).
std::unique_ptr<CameraMotion> make_camera_motion(const Scene& scene);

// A pose with the scene's frustum, looking along `forward` with `up` (both unit, orthogonal).
CameraPose pose_with_frustum(const CameraDef& camera, const Eigen::Vector3d& eye_m,
                             const Eigen::Vector3d& forward, const Eigen::Vector3d& up);

// A pose looking from `eye_m` toward `target_m`, up as close to world y as the view allows.
CameraPose pose_looking_at(const CameraDef& camera, const Eigen::Vector3d& eye_m,
                           const Eigen::Vector3d& target_m);

}  // namespace fragsim
