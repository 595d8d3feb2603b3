#include "strategies/near_plane_strategy.hpp"

#include <algorithm>
#include <cmath>

namespace fragsim {

void NearPlaneStrategy::step(const StepContext& ctx, SceneStepOutput& out) {
  // The near plane chosen is the one the next frame is drawn with, so it looks at where the
  // fragments and the camera will be after this step (semi-implicit Euler, as the physics does).
  CameraPose next = ctx.camera;
  next.eye_m += ctx.camera_velocity_mps * ctx.dt_s;
  double nearest_m = ctx.camera.near_m;
  for (const FragmentState& f : ctx.fragments) {
    const Eigen::Vector3d v = f.velocity_mps + ctx.gravity_mps2 * ctx.dt_s;
    for (const Eigen::Vector3d& p : {f.position_m, Eigen::Vector3d(f.position_m + v * ctx.dt_s)}) {
      const Eigen::Vector3d c = next.to_camera(p);
      const double front_m = c.z() - f.radius_m;  // nearest depth of its bounding sphere
      if (front_m >= nearest_m + params_.margin_m) continue;
      if (c.z() + f.radius_m <= 0.0) continue;  // wholly behind the eye, so not drawn
      // Only fragments that reach into the frustum's opening near the eye matter.
      const double depth_m = std::max(front_m, 0.0);
      if (std::abs(c.x()) > next.half_width_at(depth_m) + f.radius_m) continue;
      if (std::abs(c.y()) > next.half_height_at(depth_m) + f.radius_m) continue;
      nearest_m = std::min(nearest_m, front_m - params_.margin_m);
    }
  }
  out.near_m = std::clamp(nearest_m, params_.min_near_m, ctx.camera.near_m);
}

}  // namespace fragsim
