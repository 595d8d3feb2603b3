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
  return {camera.to_camera(f.position_m), camera_aligned_extents(camera, f), camera.near_m,
          camera.near_half_width_m(), camera.near_half_height_m()};
}

namespace {

// Adds |x(s)| <= limit(s), with x and limit linear between the two ends.
void keep_within(LinearInterval& iv, double x0, double x1, double lim0, double lim1) {
  iv.keep_nonpositive(x0 - lim0, (x1 - lim1) - (x0 - lim0));
  iv.keep_nonpositive(-x0 - lim0, (-x1 - lim1) - (-x0 - lim0));
}

}  // namespace

std::optional<double> sweep_meets_near_rectangle(const SweepEnd& a, const SweepEnd& b) {
  const Eigen::Vector3d e = a.extents_m.cwiseMax(b.extents_m);
  LinearInterval iv;
  // Depth: the box spans the near plane.
  keep_within(iv, a.centre_m.z() - a.near_m, b.centre_m.z() - b.near_m, e.z(), e.z());
  // Across: the box reaches into the rectangle.
  keep_within(iv, a.centre_m.x(), b.centre_m.x(), a.near_half_width_m + e.x(),
              b.near_half_width_m + e.x());
  keep_within(iv, a.centre_m.y(), b.centre_m.y(), a.near_half_height_m + e.y(),
              b.near_half_height_m + e.y());
  if (iv.empty()) return std::nullopt;
  return iv.lo();
}

std::optional<double> sweep_meets_camera_body(const SweepEnd& a, const SweepEnd& b,
                                              const Eigen::Vector3d& body_half_m) {
  const Eigen::Vector3d e = a.extents_m.cwiseMax(b.extents_m) + body_half_m;
  LinearInterval iv;
  for (int i = 0; i < 3; ++i) keep_within(iv, a.centre_m[i], b.centre_m[i], e[i], e[i]);
  if (iv.empty()) return std::nullopt;
  return iv.lo();
}

}  // namespace fragsim
