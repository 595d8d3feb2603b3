#pragma once
// The camera's view volume and its image: tan(fovy / 2), the frustum's cross-section at a depth,
// the sphere cull, and the projection of camera-space points (x right, y up, z = depth along the
// view) to normalized and pixel coordinates. The simulation's cull, the metrics, the strategies
// and the renderer all derive their view geometry here, so they agree to the last bit.

#include <Eigen/Core>
#include <cmath>

namespace fragsim {

inline constexpr double kPi = 3.14159265358979323846;

// Written once, in the operation order every pinned result is computed with, since a change of
// order here (say fovy * (kPi / 360)) would move the last bit and every pinned result with it.
inline double tan_half_fovy(double fovy_deg) {
  return std::tan(0.5 * fovy_deg * kPi / 180.0);
}

// A frustum as settings state it, and the one home of its defaults, which a scene's camera
// (sim/scene.hpp), a camera pose (camera_pose.hpp), the strategies' parameter rules and the C API's
// default camera all start from.
struct FrustumDef {
  double fovy_deg = 60.0;  // vertical field of view
  double aspect = 16.0 / 9.0;
  double near_m = 0.1;
  double far_m = 500.0;

  bool operator==(const FrustumDef&) const = default;
};
inline constexpr FrustumDef kDefaultFrustum{};

// A symmetric perspective frustum with its apex at the eye, in camera coordinates.
class Frustum {
 public:
  Frustum(double fovy_deg, double aspect, double near_m, double far_m)
      : tan_y_(tan_half_fovy(fovy_deg)),
        tan_x_(tan_y_ * aspect),
        aspect_(aspect),
        near_m_(near_m),
        far_m_(far_m),
        side_norm_x_(std::sqrt(1.0 + tan_x_ * tan_x_)),
        side_norm_y_(std::sqrt(1.0 + tan_y_ * tan_y_)) {}

  double tan_x() const { return tan_x_; }  // half width per metre of depth
  double tan_y() const { return tan_y_; }  // half height per metre of depth
  double aspect() const { return aspect_; }
  double near_m() const { return near_m_; }
  double far_m() const { return far_m_; }

  // Half extents of the cross-section at view depth `depth_m`. The width scales the height
  // (aspect * (depth * tan_y)) rather than using tan_x, as CameraPose uses that order and
  // depth * tan_x rounds differently.
  double half_height_at(double depth_m) const { return depth_m * tan_y_; }
  double half_width_at(double depth_m) const { return aspect_ * half_height_at(depth_m); }

  // A camera-space point in units of the cross-section at its own depth, on screen in [-1, 1]^2.
  Eigen::Vector2d normalized(const Eigen::Vector3d& p_m) const {
    return {p_m.x() / half_width_at(p_m.z()), p_m.y() / half_height_at(p_m.z())};
  }

  // Signed distances from the nearer side plane of each pair (through the eye), positive outside.
  double side_distance_x(const Eigen::Vector3d& p_m) const {
    return (std::abs(p_m.x()) - tan_x_ * p_m.z()) / side_norm_x_;
  }
  double side_distance_y(const Eigen::Vector3d& p_m) const {
    return (std::abs(p_m.y()) - tan_y_ * p_m.z()) / side_norm_y_;
  }

  // Whether a sphere (camera-space centre) may show (not wholly in front of depth front_m, beyond
  // the far plane or outside a side plane). A conservative cull (near the frustum's edges a sphere
  // outside it can pass). front_m is a parameter because the near plane is not always the bound
  // (the simulation culls from the eye, since the near-plane strategy moves the plane). Non-finite
  // input that gets past the depth tests is answered false by the last comparison.
  bool sphere_may_show(const Eigen::Vector3d& centre_m, double radius_m, double front_m) const {
    if (centre_m.z() + radius_m < front_m || centre_m.z() - radius_m > far_m_) return false;
    if (side_distance_x(centre_m) > radius_m) return false;
    return side_distance_y(centre_m) <= radius_m;
  }
  bool sphere_may_show(const Eigen::Vector3d& centre_m, double radius_m) const {
    return sphere_may_show(centre_m, radius_m, near_m_);
  }

 private:
  double tan_y_;
  double tan_x_;
  double aspect_;
  double near_m_;
  double far_m_;
  double side_norm_x_;  // lengths of the side planes' unnormalised normals (1, 0, -tan)
  double side_norm_y_;
};

// A point on the image in pixels (x from the left edge, y DOWN from the top edge).
struct ScreenPoint {
  double x = 0.0;
  double y = 0.0;
};

// The frustum's [-1, 1]^2 mapped onto a width_px x height_px image (pixel (col, row) spans
// [col, col + 1] x [row, row + 1]), as the renderer and the occlusion raster both draw it.
class PixelProjection {
 public:
  PixelProjection() = default;
  PixelProjection(const Frustum& frustum, int width_px, int height_px)
      : centre_x_px_(0.5 * width_px),
        centre_y_px_(0.5 * height_px),
        scale_x_px_(0.5 * width_px / frustum.tan_x()),
        scale_y_px_(0.5 * height_px / frustum.tan_y()) {}

  // A camera-space point with z > 0; y flips because rows count down from the top.
  ScreenPoint project(const Eigen::Vector3d& p_m) const {
    return {centre_x_px_ + scale_x_px_ * p_m.x() / p_m.z(),
            centre_y_px_ - scale_y_px_ * p_m.y() / p_m.z()};
  }
  // The camera-space direction (x / z, y / z, 1) through the centre of pixel (col, row).
  Eigen::Vector3d pixel_direction(int col, int row) const {
    return {(col + 0.5 - centre_x_px_) / scale_x_px_, (centre_y_px_ - (row + 0.5)) / scale_y_px_,
            1.0};
  }
  double scale_x_px() const { return scale_x_px_; }  // pixels per unit of x / z
  double scale_y_px() const { return scale_y_px_; }  // pixels per unit of y / z

 private:
  double centre_x_px_ = 0.0;
  double centre_y_px_ = 0.0;
  double scale_x_px_ = 0.0;
  double scale_y_px_ = 0.0;
};

}  // namespace fragsim
