#pragma once
// The ballistic path x(t) = p0 + v0 t + a t^2 / 2, one type for everyone, with the full
// acceleration a, its form relative to a (moving) point or a camera, and one coordinate's
// coefficients c0 + c1 t + c2 t^2 (c2 = a / 2). Halving is exact in binary floating point (short of
// the subnormal range), so code that stores half the acceleration gets the same bits from
// half_accel_mps2() or axis().

#include <Eigen/Core>

#include "control/geometry/camera_pose.hpp"

namespace fragsim {

// One coordinate of a parabola, c0 + c1 t + c2 t^2.
struct AxisQuadratic {
  double c0 = 0.0;
  double c1 = 0.0;
  double c2 = 0.0;  // half the acceleration

  // Horner's form, one rounding fewer than the expanded sum and the order of edge-min's slabs.
  double at(double t_s) const { return c0 + t_s * (c1 + t_s * c2); }
};

struct Parabola {
  Eigen::Vector3d p0_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d v0_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d accel_mps2 = Eigen::Vector3d::Zero();  // the full acceleration

  // The expanded sum p0 + v0 t + ((a / 2) t) t, not Horner's, as the collision prediction uses that
  // order (Horner's form rounds differently).
  Eigen::Vector3d at(double t_s) const {
    return p0_m + v0_mps * t_s + 0.5 * accel_mps2 * t_s * t_s;
  }
  Eigen::Vector3d half_accel_mps2() const { return 0.5 * accel_mps2; }

  // The same path seen from a fixed point, or from a point moving at constant velocity.
  Parabola relative_to(const Eigen::Vector3d& point_m) const {
    return {p0_m - point_m, v0_mps, accel_mps2};
  }
  Parabola relative_to(const Eigen::Vector3d& point_m,
                       const Eigen::Vector3d& point_velocity_mps) const {
    return {p0_m - point_m, v0_mps - point_velocity_mps, accel_mps2};
  }

  // Coordinate k (0, 1, 2) as c0 + c1 t + c2 t^2.
  AxisQuadratic axis(int k) const { return {p0_m[k], v0_mps[k], 0.5 * accel_mps2[k]}; }
};

// The path in camera coordinates (x right, y up, z depth) as seen from a camera that keeps its
// orientation and moves at camera_velocity_mps, rotated after subtracting, so each coordinate is
// one dot product of the world difference.
inline Parabola in_camera_frame(const Parabola& path, const CameraPose& camera,
                                const Eigen::Vector3d& camera_velocity_mps) {
  return {camera.to_camera(path.p0_m), camera.dir_to_camera(path.v0_mps - camera_velocity_mps),
          camera.dir_to_camera(path.accel_mps2)};
}

}  // namespace fragsim
