#pragma once
// Swept overlap tests in camera coordinates. Between two snapshots a fragment's centre is taken to
// move on the straight line between its camera-space positions, and its box is bounded by its
// camera-aligned extents (geometry/camera_box.hpp); every bound in the test is then linear in the
// step fraction s, so the overlap interval is exact for that motion (a fast fragment cannot jump a
// thin target). A convex piece (FragmentState::shape) is bounded the same way by its hull's own
// camera-aligned box (geometry/camera_hull.hpp), which reaches as far as its farthest vertex on
// each side of each axis and no further: tighter than its body box, still conservative for the
// polytope itself near the rectangle's corners and edges (where the hull's extreme vertex along
// one axis is not at the near plane's depth).

#include <Eigen/Core>
#include <optional>

#include "geometry/camera_box.hpp"
#include "geometry/camera_hull.hpp"
#include "geometry/camera_pose.hpp"
#include "geometry/fragment_state.hpp"

namespace fragsim {

// The sub-interval [s0, s1] of [0, 1] on which  a + b s <= 0  holds for every constraint added.
class LinearInterval {
 public:
  // Keeps the part of the interval where a + b s <= 0.
  void keep_nonpositive(double a, double b);
  bool empty() const { return lo_ > hi_; }
  double lo() const { return lo_; }
  double hi() const { return hi_; }

 private:
  double lo_ = 0.0;
  double hi_ = 1.0;
};

// One end of a sweep: the fragment's centre in that snapshot's camera frame, how far it reaches
// from the centre along the camera's +x, +y, +z (extents_m) and -x, -y, -z (extents_minus_m: the
// same as extents_m for a box, not for a hull), and that snapshot's near distance and near half
// sizes.
struct SweepEnd {
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d extents_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d extents_minus_m = Eigen::Vector3d::Zero();
  double near_m = 0.0;
  double near_half_width_m = 0.0;
  double near_half_height_m = 0.0;
};

SweepEnd sweep_end(const CameraPose& camera, const FragmentState& f);

// The first step fraction at which the box (or the hull's box) meets the near rectangle, if it
// does.
std::optional<double> sweep_meets_near_rectangle(const SweepEnd& a, const SweepEnd& b);

// The first step fraction at which the box meets a camera-aligned box of half size body_half_m
// centred on the eye, if it does.
std::optional<double> sweep_meets_camera_body(const SweepEnd& a, const SweepEnd& b,
                                              const Eigen::Vector3d& body_half_m);

}  // namespace fragsim
