#include "strategies/cheap_rejection.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "strategies/lanes.hpp"

namespace fragsim {
namespace {

using lanes::Lanes;
using lanes::Mask;

// ---- The ball ----------------------------------------------------------------------------------

// The margin on Q = |x|^2 - R^2, relative to S = extent^2 + R_max^2, which bounds every term of Q
// on the interval. The exact solve judges Q "zero" within 4 eps of the terms' size and rounds
// its coefficients to a few eps of S: together under 1e-14 S. A margin of 1e-9 S is 1e5 times
// that, and a few micrometres of distance on a scene's metres.
constexpr double kBallMargin = 1e-9;

// Levels of halving after the whole interval: pieces of 1/2, 1/4 and 1/8 of it.
constexpr int kBallSplits = 3;

[[gnu::always_inline]] inline Lanes l1(const Lanes (&x)[3]) {
  return lanes::abs(x[0]) + lanes::abs(x[1]) + lanes::abs(x[2]);
}

[[gnu::always_inline]] inline Lanes dot(const Lanes (&x)[3], const Lanes (&y)[3]) {
  return x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
}

// Q's Bernstein coefficients on a piece, the margin, and what they say about the piece.
struct BallPiece {
  Lanes b[5];
  Mask clear;   // every coefficient above the margin: Q > 0 on the piece
  Mask inside;  // Q below -margin at an end of the piece: the path is in the ball there
};

[[gnu::always_inline]] inline void classify(BallPiece& p, Lanes tol) {
  p.clear = lanes::gt(p.b[0], tol);
  for (int i = 1; i < 5; ++i) p.clear = p.clear & lanes::gt(p.b[i], tol);
  p.inside = lanes::lt(p.b[0], -tol) | lanes::lt(p.b[4], -tol);
}

// The whole interval [0, t_end], for two paths: Q's power coefficients (as
// ball_contact_quartic), scaled to [0, 1], then Bernstein's. Not usable (never clear) when the
// margin or the interval is not a finite, non-negative number, or the path does not start
// clearly outside the ball.
struct BallStart {
  BallPiece piece;
  Lanes tol;
  Mask usable;
};
[[gnu::always_inline]] inline BallStart ball_start(const Lanes (&d)[3], const Lanes (&v)[3],
                                                   const Lanes (&a)[3], Lanes r0, Lanes growth,
                                                   Lanes t_end) {
  const Lanes t2 = t_end * t_end;
  const Lanes c0 = dot(d, d) - r0 * r0;
  const Lanes a1 = (2.0 * dot(d, v) - 2.0 * r0 * growth) * t_end;
  const Lanes a2 = (dot(v, v) + 2.0 * dot(d, a) - growth * growth) * t2;
  const Lanes a3 = 2.0 * dot(v, a) * (t2 * t_end);
  const Lanes a4 = dot(a, a) * (t2 * t2);
  // b_i = sum_k C(i, k) / C(4, k) a_k.
  BallStart s;
  s.piece.b[0] = c0;
  s.piece.b[1] = c0 + 0.25 * a1;
  s.piece.b[2] = c0 + 0.5 * a1 + (1.0 / 6.0) * a2;
  s.piece.b[3] = c0 + 0.75 * a1 + 0.5 * a2 + 0.25 * a3;
  s.piece.b[4] = c0 + a1 + a2 + a3 + a4;
  const Lanes extent = l1(d) + l1(v) * t_end + l1(a) * t2;
  const Lanes r_max = r0 + growth * t_end;
  s.tol = kBallMargin * (extent * extent + r_max * r_max);
  classify(s.piece, s.tol);
  const Lanes zero{};
  s.usable = lanes::ge(t_end, zero) & lanes::eq(s.tol - s.tol, zero) & lanes::gt(c0, s.tol);
  return s;
}

// De Casteljau at the middle: the coefficients of the two halves.
[[gnu::always_inline]] inline void split(const Lanes (&b)[5], Lanes (&left)[5], Lanes (&right)[5]) {
  Lanes m[5] = {b[0], b[1], b[2], b[3], b[4]};
  left[0] = m[0];
  right[4] = m[4];
  for (int level = 1; level < 5; ++level) {
    for (int i = 0; i + level < 5; ++i) m[i] = 0.5 * (m[i] + m[i + 1]);
    left[level] = m[0];
    right[4 - level] = m[4 - level];
  }
}

// Lane 0's piece (both lanes carry the same path): clear, halving where in doubt.
bool ball_piece_clears(const BallPiece& p, Lanes tol, int splits) {
  if (lanes::get(p.clear, 0)) return true;
  if (lanes::get(p.inside, 0) || splits == 0) return false;
  BallPiece halves[2];
  split(p.b, halves[0].b, halves[1].b);
  for (BallPiece& h : halves) {
    classify(h, tol);
    if (!ball_piece_clears(h, tol, splits - 1)) return false;
  }
  return true;
}

void broadcast3(const Eigen::Vector3d& x, Lanes (&out)[3]) {
  for (int i = 0; i < 3; ++i) out[i] = lanes::broadcast(x[i]);
}

// ---- The box -----------------------------------------------------------------------------------

// The margin, relative to the path's extent and the box's size: the exact solves find the times a
// coordinate meets a face to within ~1e-15 of those sizes (in the coordinate); 1e-6 is a
// million times that, micrometres on a scene's metres.
constexpr double kBoxMargin = 1e-6;

// The acceleration (halved) shared by the paths of a box test, with the reciprocals its vertex
// times and roots need: a multiplication instead of a division per path. The times come out
// within an ulp or two of the quotients, far inside the margin.
struct BoxAccel {
  Lanes a[3];
  Lanes inv_2a[3];  // 1 / (2 a), or 0 where a = 0 (no vertex)
  Lanes inv_a_z;    // 1 / a_z, or 0
  bool curved[3];   // a != 0
  Lanes reach_m;    // |a|_1 t_end^2 + |lo|_1 + |hi|_1: the part of the margin's scale all share
};
BoxAccel box_accel(const Eigen::Vector3d& a_mps2, const Eigen::Vector3d& lo_m,
                   const Eigen::Vector3d& hi_m, double t_end_s) {
  BoxAccel acc;
  for (int i = 0; i < 3; ++i) {
    acc.a[i] = lanes::broadcast(a_mps2[i]);
    acc.curved[i] = a_mps2[i] != 0.0;
    acc.inv_2a[i] = lanes::broadcast(acc.curved[i] ? 1.0 / (2.0 * a_mps2[i]) : 0.0);
  }
  acc.inv_a_z = acc.inv_2a[2] + acc.inv_2a[2];
  acc.reach_m = lanes::broadcast(a_mps2.lpNorm<1>() * t_end_s * t_end_s + lo_m.lpNorm<1>() +
                                 hi_m.lpNorm<1>());
  return acc;
}

[[gnu::always_inline]] inline Lanes at(Lanes c0, Lanes c1, Lanes c2, Lanes t) {
  return c0 + t * (c1 + t * c2);
}

// Whether c0 + c1 t + c2 t^2 stays outside [lo, hi] over [t0, t1]: its range there (the ends,
// and the vertex where it lies inside) misses the slab. `curved` says c2 != 0 (the same for all
// paths: the acceleration's component).
[[gnu::always_inline]] inline Mask misses(Lanes c0, Lanes c1, Lanes c2, Lanes inv_2c2, bool curved,
                                          Lanes t0, Lanes t1, Lanes lo, Lanes hi) {
  const Lanes f0 = at(c0, c1, c2, t0);
  const Lanes f1 = at(c0, c1, c2, t1);
  Lanes low = lanes::min(f0, f1);
  Lanes high = lanes::max(f0, f1);
  if (curved) {
    const Lanes ts = -c1 * inv_2c2;
    const Mask vertex_inside = lanes::gt(ts, t0) & lanes::lt(ts, t1);
    const Lanes fv = lanes::select(vertex_inside, at(c0, c1, c2, ts), f0);
    low = lanes::min(low, fv);
    high = lanes::max(high, fv);
  }
  return lanes::lt(high, lo) | lanes::gt(low, hi);
}

// Widens [first, last] to hold t where `ok` and 0 <= t <= t_end.
[[gnu::always_inline]] inline void include(Mask ok, Lanes t, Lanes t_end, Lanes& first,
                                           Lanes& last) {
  const Mask in = ok & lanes::ge(t, Lanes{}) & lanes::le(t, t_end);
  first = lanes::select(in, lanes::min(first, t), first);
  last = lanes::select(in, lanes::max(last, t), last);
}

// The box grown by `grow` and kept `tol` away: lo - grow - tol <= x(t) <= hi + grow + tol. Not
// usable (never clear) when the margin or the interval is not a finite, non-negative number.
struct GrownBox {
  Lanes lo[3];
  Lanes hi[3];
  Mask usable;
};
[[gnu::always_inline]] inline GrownBox grow_box(const Lanes (&d)[3], const Lanes (&v)[3],
                                                const BoxAccel& acc, const Lanes (&lo_m)[3],
                                                const Lanes (&hi_m)[3], Lanes grow, Lanes t_end) {
  // The scale bounds every coordinate's reach and the grown box's faces (|lo - grow| <= |lo| +
  // grow).
  const Lanes scale = l1(d) + l1(v) * t_end + acc.reach_m + 6.0 * lanes::abs(grow);
  const Lanes tol = kBoxMargin * scale;
  GrownBox box;
  for (int i = 0; i < 3; ++i) {
    box.lo[i] = lo_m[i] - grow - tol;
    box.hi[i] = hi_m[i] + grow + tol;
  }
  const Lanes zero{};
  box.usable = lanes::eq(tol - tol, zero) & lanes::ge(t_end, zero);
  return box;
}

// The first stage: some coordinate stays outside its slab over the whole interval.
[[gnu::always_inline]] inline Mask box_ranges_miss(const Lanes (&d)[3], const Lanes (&v)[3],
                                                   const BoxAccel& acc, const GrownBox& box,
                                                   Lanes t_end) {
  const Lanes zero{};
  Mask miss =
      misses(d[0], v[0], acc.a[0], acc.inv_2a[0], acc.curved[0], zero, t_end, box.lo[0], box.hi[0]);
  for (int i = 1; i < 3; ++i) {
    miss |= misses(d[i], v[i], acc.a[i], acc.inv_2a[i], acc.curved[i], zero, t_end, box.lo[i],
                   box.hi[i]);
  }
  return miss;
}

// The second stage: x or y stays outside its slab over the times z is inside its own. Those
// times lie between the first and the last of: the ends of [0, t_end] where z is inside, and the
// times z crosses a face (stable quadratic roots).
[[gnu::always_inline]] inline Mask box_window_miss(const Lanes (&d)[3], const Lanes (&v)[3],
                                                   const BoxAccel& acc, const GrownBox& box,
                                                   Lanes t_end) {
  const Lanes zero{};
  Lanes first = lanes::broadcast(INFINITY);
  Lanes last = lanes::broadcast(-INFINITY);
  for (const Lanes t : {zero, t_end}) {
    const Lanes z = at(d[2], v[2], acc.a[2], t);
    include(lanes::ge(z, box.lo[2]) & lanes::le(z, box.hi[2]), t, t_end, first, last);
  }
  const Lanes a = acc.a[2];
  const Lanes b = v[2];
  for (const Lanes face : {box.lo[2], box.hi[2]}) {
    const Lanes c = d[2] - face;
    if (!acc.curved[2]) {
      include(lanes::ne(b, zero), -c / b, t_end, first, last);
      continue;
    }
    const Lanes disc = b * b - 4.0 * a * c;
    const Lanes q = -0.5 * (b + lanes::copysign(lanes::sqrt(disc), b));
    include(lanes::ge(disc, zero), q * acc.inv_a_z, t_end, first, last);
    include(lanes::ge(disc, zero) & lanes::ne(q, zero), c / q, t_end, first, last);
  }
  const Mask window = lanes::le(first, last);
  // x and y over that window, widened anyway: roots good to rounding, a multiplied reciprocal.
  const Lanes widen = kBoxMargin * t_end;
  const Lanes w0 = lanes::max(first - widen, zero);
  const Lanes w1 = lanes::min(last + widen, t_end);
  Mask miss = ~window;
  for (int i = 0; i < 2; ++i) {
    miss |= window & misses(d[i], v[i], acc.a[i], acc.inv_2a[i], acc.curved[i], w0, w1, box.lo[i],
                            box.hi[i]);
  }
  return miss;
}

// Both stages: the box test for two paths at once.
[[gnu::always_inline]] inline Mask box_clear(const Lanes (&d)[3], const Lanes (&v)[3],
                                             const BoxAccel& acc, const Lanes (&lo_m)[3],
                                             const Lanes (&hi_m)[3], Lanes grow, Lanes t_end) {
  const GrownBox box = grow_box(d, v, acc, lo_m, hi_m, grow, t_end);
  return box.usable &
         (box_ranges_miss(d, v, acc, box, t_end) | box_window_miss(d, v, acc, box, t_end));
}

}  // namespace

// ---- The ball, one path and many ---------------------------------------------------------------

bool path_clears_ball(const RelativePath& path, double r0_m, double growth_mps, double t_end_s) {
  // Both lanes carry this path: the same arithmetic, so the same answers, as BallClearance.
  Lanes d[3];
  Lanes v[3];
  Lanes a[3];
  broadcast3(path.d_m, d);
  broadcast3(path.v_mps, v);
  broadcast3(path.a_mps2, a);
  const BallStart s = ball_start(d, v, a, lanes::broadcast(r0_m), lanes::broadcast(growth_mps),
                                 lanes::broadcast(t_end_s));
  if (!lanes::get(s.usable, 0)) return false;
  return ball_piece_clears(s.piece, s.tol, kBallSplits);
}

void BallClearance::resize(std::size_t n) {
  // Room for a whole number of lane pairs; a spare path never clears (t_end < 0).
  const std::size_t padded = n + n % lanes::kWidth;
  for (auto* x : {&dx_, &dy_, &dz_, &vx_, &vy_, &vz_, &r0_, &t_end_}) x->resize(padded);
  if (padded > n) set(n, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), 0.0, -1.0);
  size_ = n;
}

std::span<const char> BallClearance::run(const Eigen::Vector3d& a_mps2, double growth_mps) {
  const std::size_t padded = t_end_.size();
  tol_.resize(padded);
  clears_.resize(padded);
  Lanes a[3];
  broadcast3(a_mps2, a);
  const Lanes growth = lanes::broadcast(growth_mps);
  // The whole interval of every path, two at a time, straight from the arrays.
  pieces_.clear();
  for (std::size_t i = 0; i < padded; i += lanes::kWidth) {
    const Lanes d[3] = {lanes::load(&dx_[i]), lanes::load(&dy_[i]), lanes::load(&dz_[i])};
    const Lanes v[3] = {lanes::load(&vx_[i]), lanes::load(&vy_[i]), lanes::load(&vz_[i])};
    const BallStart s = ball_start(d, v, a, lanes::load(&r0_[i]), growth, lanes::load(&t_end_[i]));
    lanes::store(&tol_[i], s.tol);
    for (int k = 0; k < lanes::kWidth; ++k) {
      clears_[i + k] = 0;
      if (!lanes::get(s.usable, k) || lanes::get(s.piece.inside, k)) continue;
      clears_[i + k] = 1;
      if (lanes::get(s.piece.clear, k)) continue;
      Piece& doubt = pieces_.emplace_back();
      doubt.path = static_cast<std::int32_t>(i + k);
      for (int c = 0; c < 5; ++c) doubt.b[c] = s.piece.b[c][k];
    }
  }
  // Pieces in doubt, halved, two at a time: a path is cleared once every one of its pieces is,
  // as path_clears_ball does.
  for (int level = 1; level <= kBallSplits && !pieces_.empty(); ++level) {
    const bool last = level == kBallSplits;
    next_.clear();
    const std::size_t m = pieces_.size();
    for (std::size_t j = 0; j < m; j += lanes::kWidth) {
      // The last piece twice at an odd end.
      const Piece* two[2] = {&pieces_[j], &pieces_[std::min(j + 1, m - 1)]};
      Lanes b[5];
      for (int c = 0; c < 5; ++c) b[c] = Lanes{two[0]->b[c], two[1]->b[c]};
      const Lanes tol{tol_[static_cast<std::size_t>(two[0]->path)],
                      tol_[static_cast<std::size_t>(two[1]->path)]};
      BallPiece halves[2];
      split(b, halves[0].b, halves[1].b);
      for (BallPiece& h : halves) {
        classify(h, tol);
        for (std::size_t k = 0; k < 2 && j + k < m; ++k) {
          const int lane = static_cast<int>(k);
          if (lanes::get(h.clear, lane)) continue;
          const std::int32_t p = two[k]->path;
          if (lanes::get(h.inside, lane) || last) {
            clears_[static_cast<std::size_t>(p)] = 0;
            continue;
          }
          Piece& doubt = next_.emplace_back();
          doubt.path = p;
          for (int c = 0; c < 5; ++c) doubt.b[c] = h.b[c][lane];
        }
      }
    }
    // The next level halves only the pieces of paths not yet ruled out.
    pieces_.clear();
    for (const Piece& piece : next_) {
      if (clears_[static_cast<std::size_t>(piece.path)]) pieces_.push_back(piece);
    }
  }
  return std::span<const char>(clears_).first(size_);
}

// ---- The box, one path and many ----------------------------------------------------------------

bool path_clears_box(const RelativePath& path, const Eigen::Vector3d& lo_m,
                     const Eigen::Vector3d& hi_m, double t_end_s) {
  // Both lanes carry this path: the same arithmetic, so the same answers, as BoxClearance.
  Lanes d[3];
  Lanes v[3];
  Lanes lo[3];
  Lanes hi[3];
  broadcast3(path.d_m, d);
  broadcast3(path.v_mps, v);
  broadcast3(lo_m, lo);
  broadcast3(hi_m, hi);
  const Mask clear = box_clear(d, v, box_accel(path.a_mps2, lo_m, hi_m, t_end_s), lo, hi, Lanes{},
                               lanes::broadcast(t_end_s));
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
  // what the full test clears. Fragments in doubt are listed without a branch: each writes its
  // index, the count advances by one where in doubt (a branch would be mispredicted often).
  const double axes_norm =
      (frame.axes[0].norm() + frame.axes[1].norm() + frame.axes[2].norm()) * (1.0 + 1e-12);
  std::size_t doubts = 0;
  for (std::size_t i = 0; i < n; i += lanes::kWidth) {
    const std::size_t i1 = std::min(i + 1, n - 1);
    const Pair p = load_pair(i, i1);
    const Lanes x0 = dot(p.rel, axes[0]);
    const Lanes vx = dot(p.rel_v, axes[0]);
    const Lanes tol = kBoxMargin * (axes_norm * (l1(p.rel) + l1(p.rel_v) * t_end) + acc.reach_m +
                                    6.0 * lanes::abs(p.radius));
    const Mask usable = lanes::eq(tol - tol, Lanes{}) & lanes::ge(t_end, Lanes{});
    const Mask clear = usable & misses(x0, vx, acc.a[0], acc.inv_2a[0], acc.curved[0], Lanes{},
                                       t_end, lo[0] - p.radius - tol, hi[0] + p.radius + tol);
    const int bits = lanes::bits(clear);
    clears_[i] = static_cast<char>(bits & 1);
    doubt_[doubts] = static_cast<std::int32_t>(i);
    doubts += static_cast<std::size_t>(1 - (bits & 1));
    clears_[i1] = static_cast<char>((bits >> 1) & 1);  // i1 = i at an odd end: the same answer
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
