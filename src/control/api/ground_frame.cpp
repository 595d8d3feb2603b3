#include "control/api/ground_frame.hpp"

#include <cmath>

#include "control/geometry/vec3_sums.hpp"

namespace fragsim::control {

GroundFrame::GroundFrame(const fragsim_vec3& n) {
  const int zeros = (n.x == 0.0) + (n.y == 0.0) + (n.z == 0.0);
  if (zeros == 2) {
    // The quarter and half turns that take the axis to +y, about z for +-x and about x for +-z and
    // -y (inside = (x, z, -y) for z-up, Blender's and Unreal's convention mapped to y-up).
    if (n.y > 0.0) {
      from_ = {0, 1, 2}, sign_ = {1.0, 1.0, 1.0};
    } else if (n.y < 0.0) {
      from_ = {0, 1, 2}, sign_ = {1.0, -1.0, -1.0};
    } else if (n.z > 0.0) {
      from_ = {0, 2, 1}, sign_ = {1.0, 1.0, -1.0};
    } else if (n.z < 0.0) {
      from_ = {0, 2, 1}, sign_ = {1.0, -1.0, 1.0};
    } else if (n.x > 0.0) {
      from_ = {1, 0, 2}, sign_ = {-1.0, 1.0, 1.0};
    } else {
      from_ = {1, 0, 2}, sign_ = {1.0, -1.0, 1.0};
    }
    return;
  }
  permutation_ = false;
  const Eigen::Vector3d u = Eigen::Vector3d(n.x, n.y, n.z).normalized();
  // (b1, b2, u) is a right-handed orthonormal basis (Duff et al. 2017, listing 3).
  const double sign = std::copysign(1.0, u.z());
  const double a = -1.0 / (sign + u.z());
  const double b = u.x() * u.y() * a;
  const Eigen::Vector3d b1(1.0 + sign * u.x() * u.x() * a, sign * b, -sign * u.x());
  const Eigen::Vector3d b2(b, sign + u.y() * u.y() * a, -u.y());
  // Rows (b2, u, b1) are right-handed since b1 x b2 = u, and R u = (0, 1, 0).
  row_[0] = b2;
  row_[1] = u;
  row_[2] = b1;
}

Eigen::Vector3d GroundFrame::in(const Eigen::Vector3d& w) const {
  if (permutation_) {
    return {sign_[0] * w[from_[0]], sign_[1] * w[from_[1]], sign_[2] * w[from_[2]]};
  }
  return {dot3(row_[0], w), dot3(row_[1], w), dot3(row_[2], w)};
}

Eigen::Vector3d GroundFrame::out(const Eigen::Vector3d& v) const {
  if (permutation_) {
    Eigen::Vector3d w;
    for (int k = 0; k < 3; ++k) w[from_[k]] = sign_[k] * v[k];
    return w;
  }
  return row_[0] * v.x() + row_[1] * v.y() + row_[2] * v.z();
}

}  // namespace fragsim::control
