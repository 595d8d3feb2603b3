#pragma once
// The change of frame behind fragsim_step_input.ground_normal. The strategies know a y-up world
// (ground at y = ground_height_m, gravity anywhere), so the API turns the caller's world into one
// where the ground's normal is +y, runs them unchanged, and turns the forces back.
//
// A proper rotation R with R n = +y (so the plane dot(n, p) = h becomes y = h, the offset kept),
// applied to every position and direction the step carries (the eye, the camera's axes, its
// velocity, gravity, the fragments' positions and velocities; not the camera's body, whose half
// sizes are along the camera's own axes), and R^T to the forces.
// - For n along a coordinate axis, R is a signed permutation, applied as "take that coordinate,
//   maybe negated", which rounds nothing. A scene given z-up is then, inside, the very scene given
//   y-up, and its forces come out the y-up forces permuted, to the bit.
// - For any other n, R's rows are (b2, n, b1) from Duff et al.'s orthonormal basis ("Building an
//   Orthonormal Basis, Revisited", JCGT 2017), which is accurate to a few ulp for every unit n,
//   including those near -z where the classic Frisvad construction cancels (the sign of n.z picks
//   the branch). n is normalised first, so R is orthonormal to rounding whatever the 1e-6 the
//   caller's normal is off by.

#include <Eigen/Core>
#include <array>

#include "fragsim/control.h"

namespace fragsim::control {

class GroundFrame {
 public:
  // The frame of normal n (finite, nonzero; checked before).
  explicit GroundFrame(const fragsim_vec3& n);
  // World to the strategies' frame, and back.
  Eigen::Vector3d in(const Eigen::Vector3d& world) const;
  Eigen::Vector3d out(const Eigen::Vector3d& inside) const;
  bool permutation() const { return permutation_; }

 private:
  bool permutation_ = true;
  // Signed permutation: inside[k] = sign_[k] * world[from_[k]].
  std::array<int, 3> from_{0, 1, 2};
  std::array<double, 3> sign_{1.0, 1.0, 1.0};
  // Otherwise the rows of R.
  Eigen::Vector3d row_[3];
};

}  // namespace fragsim::control
