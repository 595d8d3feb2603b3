#pragma once
// Swept overlap tests in camera coordinates. Between two snapshots a fragment's centre is taken to
// move on the straight line between its camera-space positions, and its box is bounded by its
// camera-aligned extents (geometry/camera_box.hpp); every bound in the test is then linear in the
// step fraction s, so the overlap interval is exact for that motion (a fast fragment cannot jump a
// thin target). A convex piece (FragmentState::shape) is bounded the same way by its hull's own
// camera-aligned box (geometry/camera_hull.hpp), which reaches as far as its farthest vertex on
// each side of each axis and no further, tighter than its body box yet conservative for the
// polytope itself (where the hull's extreme vertex along one axis is not at the near plane's
// depth, or lies beyond the rectangle along the other). HullSweep below is the exact test of the
// polytope, for what that box flags.

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "control/geometry/camera_pose.hpp"
#include "control/geometry/fragment_state.hpp"
#include "geometry/camera_box.hpp"
#include "geometry/camera_hull.hpp"

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

// One end of a sweep, the fragment's centre in that snapshot's camera frame, how far it reaches
// from the centre along the camera's +x, +y, +z (extents_m) and -x, -y, -z (extents_minus_m, the
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

// The exact near-rectangle test of a convex piece (FragmentState::shape) over a step, for the
// swept test's motion, the centre on the straight line between its camera-space positions and
// about it the hull of the piece's vertices in both end orientations (so a piece that does not
// turn within the step is the polytope itself, translated; one that turns is bounded by both its
// end poses, as the box's extents bound a box). Exact where sweep_meets_near_rectangle bounds the
// hull by its camera-aligned box, which the metrics ask first, so this runs only on the few pieces
// that box flags.
//
// In (s, x, y, z) the swept piece is the convex hull of its vertices at s = 0 and at s = 1. The
// near plane z = near(s) cuts it in the hull of the points where the segments between those
// vertices cross the plane. Dividing x and y by near(s) (a projective map, so hulls stay hulls)
// makes the near rectangle one fixed rectangle, and the test is a 2-D separating-axis one.
// Holds its scratch, so a metric that keeps one allocates nothing once it has grown.
class HullSweep {
 public:
  bool meets_near_rectangle(const CameraPose& camera_a, const FragmentState& a,
                            const CameraPose& camera_b, const FragmentState& b);

 private:
  std::vector<Eigen::Vector3d> offsets_a_m_;  // camera-space vertices about the centre, end a
  std::vector<Eigen::Vector3d> offsets_b_m_;
  std::vector<Eigen::Vector4d> points_;  // (s, x, y, z - near(s)) of the swept hull's vertices
  std::vector<Eigen::Vector2d> section_;
  std::vector<Eigen::Vector2d> hull_;
};

// The first step fraction at which the box meets a camera-aligned box of half size body_half_m
// centred on the eye, if it does.
std::optional<double> sweep_meets_camera_body(const SweepEnd& a, const SweepEnd& b,
                                              const Eigen::Vector3d& body_half_m);

}  // namespace fragsim
