#include "near_plane_check.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace {

// Squared distance of a point to the rectangle (camera frame).
double squared_distance_to_rectangle(const NearRectangle& rect, Vec3 p) {
  const double dx = std::max(std::abs(p.x) - rect.half_width_m, 0.0);
  const double dy = std::max(std::abs(p.y) - rect.half_height_m, 0.0);
  const double dz = p.z - rect.distance_m;
  return dx * dx + dy * dy + dz * dz;
}

// Squared distance between segments p1-q1 and p2-q2 (q2 != p2): the closest points by clamping
// each segment's parameter in turn, the classic closed form.
double squared_distance_between_segments(Vec3 p1, Vec3 q1, Vec3 p2, Vec3 q2) {
  const Vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
  double s = 0, t = 0;
  if (a <= 1e-30) {  // the first segment is a point (a fragment at rest)
    t = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = dot(d1, r), b = dot(d1, d2);
    const double denominator = a * e - b * b;  // 0 for parallel segments: any s will do
    s = denominator > 0 ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
    t = (b * s + f) / e;
    if (t < 0) {
      t = 0;
      s = std::clamp(-c / a, 0.0, 1.0);
    } else if (t > 1) {
      t = 1;
      s = std::clamp((b - c) / a, 0.0, 1.0);
    }
  }
  const Vec3 gap = (p1 + d1 * s) - (p2 + d2 * t);
  return dot(gap, gap);
}

}  // namespace

NearRectangle near_rectangle(double near_m, double fovy_deg, double aspect) {
  NearRectangle rect;
  rect.distance_m = near_m;
  rect.half_height_m = near_m * std::tan(0.5 * fovy_deg * std::numbers::pi / 180.0);
  rect.half_width_m = rect.half_height_m * aspect;
  return rect;
}

Vec3 to_camera_frame(Vec3 point_m, Vec3 eye_m, Vec3 right, Vec3 up, Vec3 forward) {
  const Vec3 d = point_m - eye_m;
  return {dot(d, right), dot(d, up), dot(d, forward)};
}

bool swept_sphere_meets(const NearRectangle& rect, Vec3 from, Vec3 to, double radius_m) {
  const double r2 = radius_m * radius_m;
  // The centre passes through the rectangle itself.
  const double before = from.z - rect.distance_m, after = to.z - rect.distance_m;
  if ((before <= 0 && after >= 0) || (before >= 0 && after <= 0)) {
    const double s = before == after ? 0.0 : before / (before - after);
    const Vec3 crossing = from + (to - from) * s;
    if (std::abs(crossing.x) <= rect.half_width_m && std::abs(crossing.y) <= rect.half_height_m) {
      return true;
    }
  }
  // Otherwise the closest points of two convex sets that do not meet lie on the boundary of one
  // of them: an end of the segment against the rectangle, or the segment against an edge.
  if (squared_distance_to_rectangle(rect, from) <= r2) return true;
  if (squared_distance_to_rectangle(rect, to) <= r2) return true;
  const double w = rect.half_width_m, h = rect.half_height_m, z = rect.distance_m;
  const Vec3 corners[4] = {{-w, -h, z}, {w, -h, z}, {w, h, z}, {-w, h, z}};
  for (int i = 0; i < 4; ++i) {
    if (squared_distance_between_segments(from, to, corners[i], corners[(i + 1) % 4]) <= r2) {
      return true;
    }
  }
  return false;
}

bool near_plane_check_agrees_with_known_cases() {
  const NearRectangle rect = near_rectangle(0.1, 60, 16.0 / 9.0);  // w 0.1026, h 0.0577 m
  const double w = rect.half_width_m, h = rect.half_height_m;
  struct Case {
    Vec3 from, to;
    double radius_m;
    bool meets;
  };
  const Case cases[] = {
      {{0, 0, 1}, {0, 0, -1}, 0.001, true},      // straight through the middle
      {{0, 0, 1}, {0, 0, 0.3}, 0.19, false},     // stops 0.2 m short
      {{0, 0, 1}, {0, 0, 0.3}, 0.21, true},      // ... with a larger sphere
      {{0.5, 0, 1}, {0.5, 0, -1}, 0.39, false},  // beside it, 0.397 m from its edge
      {{0.5, 0, 1}, {0.5, 0, -1}, 0.40, true},   //
      {{-1, h + 0.03, 0.14}, {1, h + 0.03, 0.14}, 0.049, false},  // across, 0.05 m above the top
      {{-1, h + 0.03, 0.14}, {1, h + 0.03, 0.14}, 0.051, true},   // edge, 0.04 m in front
      {{w + 0.3, h + 0.4, 0.1}, {w + 0.3, h + 0.4, 0.1}, 0.49, false},  // at rest, 0.5 m off
      {{w + 0.3, h + 0.4, 0.1}, {w + 0.3, h + 0.4, 0.1}, 0.51, true},   // the corner
      {{2, 0, 0.5}, {-2, 0, -0.3}, 0.001, true},  // a fast diagonal pass through it
  };
  for (const Case& c : cases) {
    if (swept_sphere_meets(rect, c.from, c.to, c.radius_m) != c.meets) return false;
  }
  return true;
}
