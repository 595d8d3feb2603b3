#pragma once
// edge's cheap rejection (cheap_rejection.hpp). A fragment's path that certainly stays outside the
// camera's reachable ball (docs/method.md section 3) needs no root solve. It only ever answers
// "certainly clear"; a path in doubt goes on to the exact solve.

#include <Eigen/Core>
#include <cstdint>
#include <span>

#include "control/geometry/parabola.hpp"
#include "control/memory/memory_resource.hpp"

namespace fragsim {

// The one-path test takes the path relative to the ball's centre (Parabola::relative_to),
// x(t) = d + v t + a t^2 with d = p0, v = v0 and a half its acceleration, for t in [0, t_end];
// the batched one takes d and v per path and the half acceleration a (`a_mps2`) shared by all.

// True when |x(t)| > r0 + growth t for every t in [0, t_end], so the path certainly stays outside
// the ball (fixed when growth = 0, growing otherwise). Q(t) = |x(t)|^2 - (r0 + growth t)^2 is a
// quartic; its Bernstein coefficients on an interval bound it there (the convex hull property), so
// all of them above the margin prove Q > 0. The whole interval first, then halves, quarters and
// eighths of it (de Casteljau's subdivision), only where still in doubt. False when in doubt
// (non-finite input, t_end < 0, a path that starts inside or is inside at a piece's end).
bool path_clears_ball(const Parabola& path, double r0_m, double growth_mps, double t_end_s);

// path_clears_ball for many paths under one acceleration and one growth.
class BallClearance {
 public:
  explicit BallClearance(MemoryResource* mem = default_memory_resource()) : mem_(mem) {}
  // Room for n paths, then each one set by index.
  void resize(std::size_t n);
  // Room for runs over up to n paths, set later by resize. Such a run allocates nothing while at
  // most two pieces per path stay in doubt.
  void reserve(std::size_t n);
  void set(std::size_t i, const Eigen::Vector3d& d_m, const Eigen::Vector3d& v_mps, double r0_m,
           double t_end_s) {
    set_path(i, d_m, v_mps);
    set_ball(i, r0_m, t_end_s);
  }
  // The same in two parts, for a caller that knows the ball only after the path.
  void set_path(std::size_t i, const Eigen::Vector3d& d_m, const Eigen::Vector3d& v_mps) {
    dx_[i] = d_m.x();
    dy_[i] = d_m.y();
    dz_[i] = d_m.z();
    vx_[i] = v_mps.x();
    vy_[i] = v_mps.y();
    vz_[i] = v_mps.z();
  }
  void set_ball(std::size_t i, double r0_m, double t_end_s) {
    r0_[i] = r0_m;
    t_end_[i] = t_end_s;
  }
  std::size_t size() const { return size_; }
  // One flag per path, in order, 1 when it clears its ball. Valid until the next call.
  std::span<const char> run(const Eigen::Vector3d& a_mps2, double growth_mps);

 private:
  // A piece of a path in doubt, the path and Q's five Bernstein coefficients on the piece.
  struct Piece {
    std::int32_t path;
    double b[5];
  };
  std::size_t size_ = 0;
  MemoryResource* mem_;
  // Padded to whole lanes.
  ResourceVector<double> dx_{mem_}, dy_{mem_}, dz_{mem_}, vx_{mem_}, vy_{mem_}, vz_{mem_},
      r0_{mem_}, t_end_{mem_};
  ResourceVector<double> tol_{mem_};
  ResourceVector<char> clears_{mem_};
  ResourceVector<Piece> pieces_{mem_};
  ResourceVector<Piece> next_{mem_};
};

}  // namespace fragsim
