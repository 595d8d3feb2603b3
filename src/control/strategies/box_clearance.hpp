#pragma once
// The box test of the cheap rejection (cheap_rejection.hpp). A fragment's path that certainly never
// has all three coordinates inside a box needs no root solve there. It only ever answers "certainly
// clear"; a path in doubt goes on to the exact solve.

#include <Eigen/Core>
#include <cstdint>
#include <span>

#include "control/geometry/fragment_state.hpp"
#include "control/geometry/parabola.hpp"
#include "control/memory/memory_resource.hpp"

namespace fragsim {

// The one-path test takes the path relative to the box's centre (Parabola::relative_to),
// x(t) = d + v t + a t^2 with d = p0, v = v0 and a half its acceleration, for t in [0, t_end];
// the batched one takes each path in world coordinates and the half acceleration a (`a_mps2`)
// shared by all.

// The axis-aligned box lo <= x(t) <= hi (per coordinate). True when no t in [0, t_end] has all
// three coordinates inside it. It checks each coordinate's range over the whole interval (ends and
// vertex), then the x and y ranges over the times z is inside its slab. False when in doubt.
bool path_clears_box(const Parabola& path, const Eigen::Vector3d& lo_m, const Eigen::Vector3d& hi_m,
                     double t_end_s);

// A moving frame for BoxClearance. Paths given in world coordinates are seen from it, x along
// axes[0], y along axes[1], z along axes[2] (a camera's right, up and forward).
struct BoxFrame {
  Eigen::Vector3d origin_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d axes[3] = {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(),
                             Eigen::Vector3d::UnitZ()};
  Eigen::Vector3d velocity_mps = Eigen::Vector3d::Zero();
};

// path_clears_box for many fragments, whose paths are given in world coordinates, seen from one
// frame, under one acceleration (in the frame's axes), against one box grown per fragment by its
// bounding radius, over one interval. A first stage (x's range alone) runs over every fragment,
// straight from their states, the full test over those it left in doubt.
class BoxClearance {
 public:
  explicit BoxClearance(MemoryResource* mem = default_memory_resource()) : mem_(mem) {}
  // One flag per fragment, 1 when, in `frame`, its path x(t) = position + velocity t + a t^2 clears
  // lo - radius <= x(t) <= hi + radius. Valid until the next call.
  std::span<const char> run(std::span<const FragmentState> fragments, const BoxFrame& frame,
                            const Eigen::Vector3d& a_mps2, const Eigen::Vector3d& lo_m,
                            const Eigen::Vector3d& hi_m, double t_end_s);

 private:
  MemoryResource* mem_;
  ResourceVector<char> clears_{mem_};
  ResourceVector<std::int32_t> doubt_{mem_};  // fragments the first stage left in doubt
};

}  // namespace fragsim
