#include "control/strategies/box_clearance.hpp"

#include <algorithm>
#include <cstdint>

#include "control/geometry/vec3_sums.hpp"
#include "control/strategies/cheap_rejection.hpp"
#include "control/strategies/lane_ops.hpp"
#include "control/strategies/lanes.hpp"

namespace fragsim {
namespace {

using lanes::Lanes;
using lanes::Mask;
using rejection::box_accel;
using rejection::box_clear;
using rejection::BoxAccel;
using rejection::broadcast3;
using rejection::dot;
using rejection::kBoxMargin;
using rejection::l1;
using rejection::misses;

}  // namespace

bool path_clears_box(const Parabola& path, const Eigen::Vector3d& lo_m, const Eigen::Vector3d& hi_m,
                     double t_end_s) {
  // Both lanes carry this path, so it gets the same arithmetic, and answers, as BoxClearance.
  Lanes d[3];
  Lanes v[3];
  Lanes lo[3];
  Lanes hi[3];
  broadcast3(path.p0_m, d);
  broadcast3(path.v0_mps, v);
  broadcast3(lo_m, lo);
  broadcast3(hi_m, hi);
  const Mask clear = box_clear(d, v, box_accel(path.half_accel_mps2(), lo_m, hi_m, t_end_s), lo, hi,
                               Lanes{}, lanes::broadcast(t_end_s));
  return lanes::get(clear, 0);
}

std::span<const char> BoxClearance::run(std::span<const FragmentState> fragments,
                                        const BoxFrame& frame, const Eigen::Vector3d& a_mps2,
                                        const Eigen::Vector3d& lo_m, const Eigen::Vector3d& hi_m,
                                        double t_end_s) {
  const std::size_t n = fragments.size();
  clears_.resize(n);
  doubt_.resize(n + 1);
  if (n == 0) return {};
  const BoxAccel acc = box_accel(a_mps2, lo_m, hi_m, t_end_s);
  const Lanes t_end = lanes::broadcast(t_end_s);
  Lanes lo[3];
  Lanes hi[3];
  Lanes origin[3];
  Lanes frame_v[3];
  Lanes axes[3][3];
  broadcast3(lo_m, lo);
  broadcast3(hi_m, hi);
  broadcast3(frame.origin_m, origin);
  broadcast3(frame.velocity_mps, frame_v);
  for (int k = 0; k < 3; ++k) broadcast3(frame.axes[k], axes[k]);
  // Two fragments' positions, velocities and radii (the last one twice at an odd end).
  struct Pair {
    Lanes rel[3];
    Lanes rel_v[3];
    Lanes radius;
  };
  const auto load_pair = [&](std::size_t i0, std::size_t i1) {
    const FragmentState& f0 = fragments[i0];
    const FragmentState& f1 = fragments[i1];
    Pair p;
    for (int k = 0; k < 3; ++k) {
      p.rel[k] = Lanes{f0.position_m[k], f1.position_m[k]} - origin[k];
      p.rel_v[k] = Lanes{f0.velocity_mps[k], f1.velocity_mps[k]} - frame_v[k];
    }
    p.radius = Lanes{f0.radius_m, f1.radius_m};
    return p;
  };
  // The first stage, over every fragment, tests x alone (most paths pass the box well to a side),
  // with a margin at least the full test's, |d|_1 <= sum |axis_k| |rel|_1, so that it clears only
  // what the full test clears. Fragments in doubt are listed without a branch, which would be
  // mispredicted often. Each writes its index, and the count advances by one where in doubt.
  const double axes_norm =
      (norm3(frame.axes[0]) + norm3(frame.axes[1]) + norm3(frame.axes[2])) * (1.0 + 1e-12);
  std::size_t doubts = 0;
  for (std::size_t i = 0; i < n; i += lanes::kWidth) {
    const std::size_t i1 = std::min(i + 1, n - 1);
    const Pair p = load_pair(i, i1);
    const Lanes x0 = dot(p.rel, axes[0]);
    const Lanes vx = dot(p.rel_v, axes[0]);
    const Lanes tol = kBoxMargin * (axes_norm * (l1(p.rel) + l1(p.rel_v) * t_end) + acc.reach_m +
                                    6.0 * lanes::abs(p.radius));
    const Mask usable = lanes::eq(tol - tol, Lanes{}) & lanes::ge(t_end, Lanes{});
    const Mask clear =
        usable & misses<NarrowOps>(x0, vx, acc.a[0], acc.minus_inv_2a[0], acc.curved[0], Lanes{},
                                   t_end, lo[0] - p.radius - tol, hi[0] + p.radius + tol);
    const int bits = lanes::bits(clear);
    clears_[i] = static_cast<char>(bits & 1);
    doubt_[doubts] = static_cast<std::int32_t>(i);
    doubts += static_cast<std::size_t>(1 - (bits & 1));
    clears_[i1] = static_cast<char>((bits >> 1) & 1);  // at an odd end i1 = i, so the same answer
    doubt_[doubts] = static_cast<std::int32_t>(i1);
    doubts += static_cast<std::size_t>(i1 > i ? 1 - ((bits >> 1) & 1) : 0);
  }
  // The full test over the rest, two at a time.
  for (std::size_t j = 0; j < doubts; j += lanes::kWidth) {
    const std::size_t i0 = static_cast<std::size_t>(doubt_[j]);
    const std::size_t i1 = static_cast<std::size_t>(doubt_[std::min(j + 1, doubts - 1)]);
    const Pair p = load_pair(i0, i1);
    Lanes d[3];
    Lanes w[3];
    for (int k = 0; k < 3; ++k) {
      d[k] = dot(p.rel, axes[k]);
      w[k] = dot(p.rel_v, axes[k]);
    }
    const int bits = lanes::bits(box_clear(d, w, acc, lo, hi, p.radius, t_end));
    clears_[i0] = static_cast<char>(bits & 1);
    clears_[i1] = static_cast<char>((bits >> 1) & 1);
  }
  return clears_;
}

}  // namespace fragsim
