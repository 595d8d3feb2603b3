#include "geometry/swept_box.hpp"

#include <algorithm>

namespace fragsim {

void LinearInterval::keep_nonpositive(double a, double b) {
  if (b == 0.0) {
    if (a > 0.0) {
      lo_ = 1.0;
      hi_ = 0.0;
    }
    return;
  }
  const double s = -a / b;
  if (b > 0.0) {
    hi_ = std::min(hi_, s);  // a + b s <= 0 for s <= -a/b
  } else {
    lo_ = std::max(lo_, s);
  }
}

SweepEnd sweep_end(const CameraPose& camera, const FragmentState& f) {
  if (f.shape) {
    const CameraExtents e = hull_camera_extents(camera, f);
    return {camera.to_camera(f.position_m),
            e.plus_m,
            e.minus_m,
            camera.near_m,
            camera.near_half_width_m(),
            camera.near_half_height_m()};
  }
  const Eigen::Vector3d e = camera_aligned_extents(camera, f);
  return {camera.to_camera(f.position_m), e, e, camera.near_m, camera.near_half_width_m(),
          camera.near_half_height_m()};
}

namespace {

// Adds -limit_plus(s) <= x(s) <= limit_minus(s), with x and both limits linear between the two
// ends: x is the centre's offset from a target, limit_minus how far the target reaches beyond it
// plus how far the piece reaches toward -x (so its low side is not past the target's high side),
// limit_plus the same on the other side. For a box both are equal and this is |x| <= limit, in
// the same operations as ever.
void keep_within(LinearInterval& iv, double x0, double x1, double lim_minus0, double lim_minus1,
                 double lim_plus0, double lim_plus1) {
  iv.keep_nonpositive(x0 - lim_minus0, (x1 - lim_minus1) - (x0 - lim_minus0));
  iv.keep_nonpositive(-x0 - lim_plus0, (-x1 - lim_plus1) - (-x0 - lim_plus0));
}

}  // namespace

std::optional<double> sweep_meets_near_rectangle(const SweepEnd& a, const SweepEnd& b) {
  // Each end's extents bound the piece in both end poses, so the orientation between the two
  // snapshots does not matter.
  const Eigen::Vector3d ep = a.extents_m.cwiseMax(b.extents_m);
  const Eigen::Vector3d em = a.extents_minus_m.cwiseMax(b.extents_minus_m);
  LinearInterval iv;
  // Depth: the piece spans the near plane.
  keep_within(iv, a.centre_m.z() - a.near_m, b.centre_m.z() - b.near_m, em.z(), em.z(), ep.z(),
              ep.z());
  // Across: the piece reaches into the rectangle.
  keep_within(iv, a.centre_m.x(), b.centre_m.x(), a.near_half_width_m + em.x(),
              b.near_half_width_m + em.x(), a.near_half_width_m + ep.x(),
              b.near_half_width_m + ep.x());
  keep_within(iv, a.centre_m.y(), b.centre_m.y(), a.near_half_height_m + em.y(),
              b.near_half_height_m + em.y(), a.near_half_height_m + ep.y(),
              b.near_half_height_m + ep.y());
  if (iv.empty()) return std::nullopt;
  return iv.lo();
}

std::optional<double> sweep_meets_camera_body(const SweepEnd& a, const SweepEnd& b,
                                              const Eigen::Vector3d& body_half_m) {
  const Eigen::Vector3d ep = a.extents_m.cwiseMax(b.extents_m) + body_half_m;
  const Eigen::Vector3d em = a.extents_minus_m.cwiseMax(b.extents_minus_m) + body_half_m;
  LinearInterval iv;
  for (int i = 0; i < 3; ++i) {
    keep_within(iv, a.centre_m[i], b.centre_m[i], em[i], em[i], ep[i], ep[i]);
  }
  if (iv.empty()) return std::nullopt;
  return iv.lo();
}

}  // namespace fragsim
