#include "control/strategies/ball_clearance.hpp"

#include <algorithm>
#include <cstdint>

#include "control/geometry/work_space.hpp"
#include "control/strategies/cheap_rejection.hpp"
#include "control/strategies/lanes.hpp"

namespace fragsim {
namespace {

using lanes::Lanes;
using lanes::Mask;
using rejection::broadcast3;
using rejection::dot;
using rejection::l1;

// The margin on Q = |x|^2 - R^2, relative to S = extent^2 + R_max^2, which bounds every term of Q
// on the interval. The exact solve judges Q "zero" within 4 eps of the terms' size and rounds its
// coefficients to a few eps of S, together under 1e-14 S. A margin of 1e-9 S is 1e5 times that, and
// a few micrometres of distance on a scene's metres.
constexpr double kBallMargin = 1e-9;

// Levels of halving after the whole interval, giving pieces of 1/2, 1/4 and 1/8 of it.
constexpr int kBallSplits = 3;

// Q's Bernstein coefficients on a piece, the margin, and what they say about the piece.
struct BallPiece {
  Lanes b[5];
  Mask clear;   // every coefficient above the margin, so Q > 0 on the piece
  Mask inside;  // Q below -margin at an end of the piece, so the path is in the ball there
};

[[gnu::always_inline]] inline void classify(BallPiece& p, Lanes tol) {
  p.clear = lanes::gt(p.b[0], tol);
  for (int i = 1; i < 5; ++i) p.clear = p.clear & lanes::gt(p.b[i], tol);
  p.inside = lanes::lt(p.b[0], -tol) | lanes::lt(p.b[4], -tol);
}

// The whole interval [0, t_end], for two paths. Q's power coefficients (as ball_contact_quartic)
// scaled to [0, 1], then Bernstein's. Not usable (never clear) when the margin or the interval is
// not a finite, non-negative number, or the path does not start clearly outside the ball.
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

// De Casteljau at the middle gives the coefficients of the two halves.
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

// Whether lane 0's piece is clear (both lanes carry the same path), halving where in doubt.
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

}  // namespace

bool path_clears_ball(const Parabola& path, double r0_m, double growth_mps, double t_end_s) {
  // Both lanes carry this path, so it gets the same arithmetic, and answers, as BallClearance.
  Lanes d[3];
  Lanes v[3];
  Lanes a[3];
  broadcast3(path.p0_m, d);
  broadcast3(path.v0_mps, v);
  broadcast3(path.half_accel_mps2(), a);
  const BallStart s = ball_start(d, v, a, lanes::broadcast(r0_m), lanes::broadcast(growth_mps),
                                 lanes::broadcast(t_end_s));
  if (!lanes::get(s.usable, 0)) return false;
  return ball_piece_clears(s.piece, s.tol, kBallSplits);
}

void BallClearance::reserve(std::size_t n) {
  const std::size_t padded = n + n % lanes::kWidth;
  for (auto* x : {&dx_, &dy_, &dz_, &vx_, &vy_, &vz_, &r0_, &t_end_, &tol_}) {
    reserve_touched(*x, padded);
  }
  reserve_touched(clears_, padded);
  reserve_touched(pieces_, 2 * n);
  reserve_touched(next_, 2 * n);
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
  // Pieces in doubt are halved two at a time; a path is cleared once all its pieces are, as in
  // path_clears_ball.
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

}  // namespace fragsim
