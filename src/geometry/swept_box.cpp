#include "geometry/swept_box.hpp"

#include <algorithm>
#include <cmath>

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
// ends. x is the centre's offset from a target, limit_minus how far the target reaches beyond it
// plus how far the piece reaches toward -x (so its low side is not past the target's high side),
// limit_plus the same on the other side. For a box both are equal, giving exactly |x| <= limit.
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
  // In depth, the piece spans the near plane.
  keep_within(iv, a.centre_m.z() - a.near_m, b.centre_m.z() - b.near_m, em.z(), em.z(), ep.z(),
              ep.z());
  // Across, the piece reaches into the rectangle.
  keep_within(iv, a.centre_m.x(), b.centre_m.x(), a.near_half_width_m + em.x(),
              b.near_half_width_m + em.x(), a.near_half_width_m + ep.x(),
              b.near_half_width_m + ep.x());
  keep_within(iv, a.centre_m.y(), b.centre_m.y(), a.near_half_height_m + em.y(),
              b.near_half_height_m + em.y(), a.near_half_height_m + ep.y(),
              b.near_half_height_m + ep.y());
  if (iv.empty()) return std::nullopt;
  return iv.lo();
}

namespace {

double cross2(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// p's hull by Andrew's monotone chain, counter-clockwise, without collinear points (1 or 2 points
// when degenerate). Sorts p.
void convex_hull_2d(std::vector<Eigen::Vector2d>& p, std::vector<Eigen::Vector2d>& hull) {
  std::sort(p.begin(), p.end(), [](const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
    return u.x() < v.x() || (u.x() == v.x() && u.y() < v.y());
  });
  hull.clear();
  if (p.size() < 3) {
    hull = p;
    return;
  }
  hull.resize(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && cross2(hull[k - 2], hull[k - 1], p[i]) <= 0.0) --k;
    hull[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross2(hull[k - 2], hull[k - 1], p[i]) <= 0.0) --k;
    hull[k++] = p[i];
  }
  hull.resize(k - 1);
}

// Whether the convex polygon (counter-clockwise; or a point or a segment) meets |x| <= w, |y| <= h:
// no separating axis among the rectangle's normals and the polygon's edge normals.
bool polygon_meets_rectangle(const std::vector<Eigen::Vector2d>& poly, double w, double h) {
  if (poly.empty()) return false;
  Eigen::Vector2d lo = poly[0];
  Eigen::Vector2d hi = poly[0];
  for (const Eigen::Vector2d& p : poly) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  if (lo.x() > w || hi.x() < -w || lo.y() > h || hi.y() < -h) return false;
  const std::size_t n = poly.size();
  if (n < 2) return true;
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d d = poly[(i + 1) % n] - poly[i];
    // A polygon lies left of its edges; a segment may be separated on either side.
    for (const double side : {1.0, -1.0}) {
      if (n >= 3 && side < 0.0) continue;
      const Eigen::Vector2d out = side * Eigen::Vector2d(d.y(), -d.x());
      // The rectangle's corner farthest toward the polygon, against the edge's line.
      if (-w * std::abs(out.x()) - h * std::abs(out.y()) > out.dot(poly[i])) return false;
    }
  }
  return true;
}

}  // namespace

bool HullSweep::meets_near_rectangle(const CameraPose& camera_a, const FragmentState& a,
                                     const CameraPose& camera_b, const FragmentState& b) {
  const double near_a = camera_a.near_m;
  const double near_b = camera_b.near_m;
  const double wa = camera_a.near_half_width_m();
  const double ha = camera_a.near_half_height_m();
  const double wb = camera_b.near_half_width_m();
  const double hb = camera_b.near_half_height_m();
  // The division by near(s) needs the rectangle's shape fixed while its distance changes; a
  // camera whose field of view changes within the step keeps the conservative answer.
  const bool fixed_near = near_a == near_b && wa == wb && ha == hb;
  const double kw = std::max(wa / near_a, wb / near_b);
  const double kh = std::max(ha / near_a, hb / near_b);
  if (!fixed_near && (std::abs(wa / near_a - wb / near_b) > 1e-12 * kw ||
                      std::abs(ha / near_a - hb / near_b) > 1e-12 * kh)) {
    return true;
  }
  const auto offsets = [](const CameraPose& cam, const FragmentState& f,
                          std::vector<Eigen::Vector3d>& out) {
    const Eigen::Matrix3d m = body_to_camera(cam, f.rotation);
    out.resize(f.shape->vertices_m.size());
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = m * f.shape->vertices_m[i];
  };
  offsets(camera_a, a, offsets_a_m_);
  offsets(camera_b, b, offsets_b_m_);
  const Eigen::Vector3d ca = camera_a.to_camera(a.position_m);
  const Eigen::Vector3d cb = camera_b.to_camera(b.position_m);
  points_.clear();
  for (const std::vector<Eigen::Vector3d>* w : {&offsets_a_m_, &offsets_b_m_}) {
    for (const Eigen::Vector3d& o : *w) {
      const Eigen::Vector3d pa = ca + o;
      const Eigen::Vector3d pb = cb + o;
      points_.emplace_back(0.0, pa.x(), pa.y(), pa.z() - near_a);
      points_.emplace_back(1.0, pb.x(), pb.y(), pb.z() - near_b);
    }
  }
  section_.clear();
  const auto add = [&](const Eigen::Vector4d& p) {
    if (fixed_near) {
      section_.emplace_back(p[1], p[2]);
    } else {
      const double n = near_a + p[0] * (near_b - near_a);
      section_.emplace_back(p[1] / n, p[2] / n);
    }
  };
  for (std::size_t i = 0; i < points_.size(); ++i) {
    const Eigen::Vector4d& u = points_[i];
    if (u[3] == 0.0) add(u);
    if (!(u[3] < 0.0)) continue;
    for (const Eigen::Vector4d& v : points_) {
      if (!(v[3] > 0.0)) continue;
      const double t = u[3] / (u[3] - v[3]);
      add(u + t * (v - u));
    }
  }
  convex_hull_2d(section_, hull_);
  return fixed_near ? polygon_meets_rectangle(hull_, wa, ha)
                    : polygon_meets_rectangle(hull_, kw, kh);
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
