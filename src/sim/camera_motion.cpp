#include "sim/camera_motion.hpp"

#include <Eigen/Geometry>
#include <cmath>

#include "sim/camera_path.hpp"
#include "sim/player_camera.hpp"
#include "sim/sampled_camera.hpp"

namespace fragsim {

CameraLimits declared_limits(const CameraDef& camera) {
  CameraLimits limits{camera.max_speed_mps, kUndeclaredBound, kUndeclaredBound};
  if (camera.mode == CameraMode::kPlayer) {
    limits.max_accel_mps2 = camera.player_accel_mps2;
    limits.max_turn_degps = camera.turn_rate_degps;
  }
  return limits;
}

std::unique_ptr<CameraMotion> make_camera_motion(const Scene& scene) {
  switch (scene.camera.mode) {
    case CameraMode::kTrack:
      return std::make_unique<SampledCamera>(scene.camera, scene.camera.track_samples);
    case CameraMode::kPlayer:
      return std::make_unique<SampledCamera>(scene.camera, player_track(scene));
    case CameraMode::kPath:
      break;
  }
  return std::make_unique<CameraPath>(scene.camera);
}

CameraPose pose_with_frustum(const CameraDef& camera, const Eigen::Vector3d& eye_m,
                             const Eigen::Vector3d& forward, const Eigen::Vector3d& up) {
  CameraPose pose;
  pose.eye_m = eye_m;
  pose.forward = forward;
  pose.up = up;
  pose.right = forward.cross(up);
  pose.fovy_deg = camera.fovy_deg;
  pose.aspect = camera.aspect;
  pose.near_m = camera.near_m;
  pose.far_m = camera.far_m;
  return pose;
}

CameraPose pose_looking_at(const CameraDef& camera, const Eigen::Vector3d& eye_m,
                           const Eigen::Vector3d& target_m) {
  Eigen::Vector3d f = target_m - eye_m;
  // Scene validation keeps look_at away from the path; this guards the instant the eye reaches it.
  if (f.norm() < 1e-9) f = Eigen::Vector3d(0, 0, -1);
  const Eigen::Vector3d forward = f.normalized();
  Eigen::Vector3d world_up(0, 1, 0);
  if (std::abs(forward.dot(world_up)) > 0.999) world_up = Eigen::Vector3d(0, 0, 1);
  const Eigen::Vector3d right = forward.cross(world_up).normalized();
  CameraPose pose = pose_with_frustum(camera, eye_m, forward, right.cross(forward));
  pose.right = right;  // as computed, not re-derived, so path camera poses keep their exact bits
  return pose;
}

}  // namespace fragsim
