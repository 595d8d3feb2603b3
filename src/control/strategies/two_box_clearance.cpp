#include "control/strategies/two_box_clearance.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <memory>
#include <optional>
#include <utility>

#include "control/geometry/vec3_sums.hpp"
#include "control/geometry/work_space.hpp"
#include "control/strategies/cheap_rejection.hpp"
#include "control/strategies/lane_ops.hpp"
#include "control/strategies/lanes.hpp"
#include "control/strategies/parallel_ranges.hpp"

namespace fragsim {
namespace {

using lanes::Lanes;
using rejection::at;
using rejection::box_accel;
using rejection::box_clear;
using rejection::BoxAccel;
using rejection::BoxAccelOf;
using rejection::broadcast3;
using rejection::dot;

// An upper bound, without a division or a square root, on the interval edge-min's solve gives a
// path (two_box_clearance.hpp), max(min(g, cap), floor) for g = EdgeMinStrategy::time_to_ground_s,
// the later root of c + b t + a t^2 (c = y - ground, b = v_y, a = half_gy < 0) going down, or 0 or
// +inf. For a < 0 that function computes disc = b b - 4 a c, s = sqrt(disc),
// q = -(b + sign(b) s) / 2 and returns max(q / a, c / q) when it is positive and the path goes
// down there.
// - If c <= 0 and (b <= 0 or disc < 0) it returns 0 (q >= 0 makes both quotients <= 0, or no root
//   is real), so the interval is the floor.
// - Otherwise it returns 0 or the later root, which is (b + s) / (2 |a|) up to a few roundings,
//   whichever quotient computes it (for b < 0 it is c / q = 2 c / (|b| + s), the same number up to
//   rounding, cancellation included, as the difference is ~eps |b| / |a|). With S >= s (1 + 1e-9),
//   (b + S) / (2 |a|) (1 + 1e-9) exceeds it by ~1e-9 (|b| + s) / |a|, far more than those roundings
//   (~1e-16 of the same). S is the least of (x / u + u) / 2 over u = 1/4, 1, 4 m/s (x / u exact),
//   at least sqrt(x) for every u > 0 (the arithmetic and geometric means) and within 25% of sqrt(x)
//   for x in [1/16, 64] (m/s)^2, the scale of a falling fragment; below, S >= 1/8 m/s still gives
//   less than a step at g = 9.81 (the floor, a fragment sliding on the ground).
// - If c > 0 it returns +inf only when the numbers under- or overflow (otherwise s > |b| there, so
//   a later root <= 0 or not going down cannot happen). Those, c or disc beyond 1e-200 .. 1e200,
//   |b| beyond 1e100, and any non-finite number, get the cap.
// For a >= 0 (no gravity down) every path gets max(cap, floor).
struct HorizonBound {
  bool down = false;  // a < 0
  double a = 0.0;
  double inv_2a = 0.0;  // 1 / (2 |a|), rounded up by 1e-9
  double cap = 0.0;
  double floor = 0.0;
};
HorizonBound horizon_bound(double half_gy_mps2, double cap_s, double floor_s) {
  HorizonBound h;
  h.down = half_gy_mps2 < 0.0;
  h.a = half_gy_mps2;
  h.inv_2a = h.down ? (1.0 + 1e-9) / (-2.0 * half_gy_mps2) : 0.0;
  h.cap = cap_s;
  h.floor = floor_s;
  return h;
}

template <class O>
[[gnu::always_inline]] inline typename O::V interval_bound(const HorizonBound& h,
                                                           const typename O::V& y0,
                                                           const typename O::V& vy,
                                                           const typename O::V& ground) {
  using V = typename O::V;
  const V cap = O::splat(h.cap);
  const V floor = O::splat(h.floor);
  if (!h.down) return O::max(cap, floor);
  const V zero = O::splat(0.0);
  const V a = O::splat(h.a);
  const V b = vy;
  const V c = y0 - ground;
  const V disc = b * b - 4.0 * a * c;  // the same number as time_to_ground_s's
  V s = 0.5 * (disc * 4.0 + 0.25);
  for (const double u : {1.0, 4.0}) s = O::min(s, 0.5 * (disc * (1.0 / u) + u));
  const V root = (b + s * (1.0 + 1e-9)) * O::splat(h.inv_2a);
  const V tiny = O::splat(1e-200);
  const V huge = O::splat(1e200);
  const auto below = O::le(c, zero);
  const auto in_range = (below | (O::ge(c, tiny) & O::ge(disc, tiny))) & O::le(c, huge) &
                        O::le(disc, huge) & O::le(O::abs(b), O::splat(1e100));
  const auto none = below & (O::le(b, zero) | O::lt(disc, zero));
  V t = O::select(in_range, root, O::splat(INFINITY));
  t = O::select(none, zero, t);
  return O::max(O::min(t, cap), floor);
}

// The first tier's test for one box. A box lo <= x <= hi in the frame's axes, grown by a fragment's
// radius r on every axis (as the exact solves grow it), lies within R + sqrt(3) r of the origin, R
// the distance to its farthest corner. Frame coordinates are x(t) = A (rel + rv t) + a t^2 (A the
// axes as rows, rel and rv world position and velocity relative to the frame), so
// |x(t)| >= sigma |rel + rv t| - |a| t^2 >= sigma (|rel| - |rv| t) - |a| t^2, sigma A's smallest
// singular value. Over [0, T] the path therefore stays beyond R + sqrt(3) r when
//   |rel| > m = k (R + sqrt(3) r + |a| T^2) + |rv|_1 T,   k >= 1 / sigma, |rv|_1 >= |rv|.
// It is tested as (1 - 1e-6) |rel|^2 > m^2, so the path stays at least 5e-7 |rel| (and 5e-7 m)
// outside that ball, beyond the solves' rounding (~1e-15 of the coordinates' size) by far, and
// beyond this test's own (a few ulps of |rel|^2 and m). Non-finite numbers never pass.
struct FarBound {
  double k_corner = INFINITY;  // k R
  double k_radius = INFINITY;  // k sqrt(3), rounded up
  double k_accel = INFINITY;   // k |a|
};
constexpr double kFarShrink = 1.0 - 1e-6;

// 1 / sigma bounded from above. A A^T's eigenvalues are sigma_i^2, and by Weyl's inequality they
// are within ||A A^T - I||_F of 1. +infinity (the first tier clears nothing) for axes far from
// orthonormal.
double inverse_sigma_bound(const Eigen::Vector3d (&axes)[3]) {
  double e2 = 0.0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const double g = dot3(axes[i], axes[j]) - (i == j ? 1.0 : 0.0);
      e2 += g * g;
    }
  }
  const double e = std::sqrt(e2) + 1e-12;  // + the rounding of e itself
  if (!(e <= 0.75)) return INFINITY;
  return (1.0 + 1e-12) / std::sqrt(1.0 - e);
}

FarBound far_bound(double k, const Eigen::Vector3d& lo_m, const Eigen::Vector3d& hi_m,
                   const Eigen::Vector3d& a_mps2) {
  const Eigen::Vector3d corner = lo_m.cwiseAbs().cwiseMax(hi_m.cwiseAbs());
  const double up = 1.0 + 1e-12;  // the rounding of the norms and products
  return {k * norm3(corner) * up, k * 1.7320508075688774 * up, k * norm3(a_mps2) * up};
}

template <class O>
[[gnu::always_inline]] inline auto stays_far(const FarBound& b, const typename O::V& rel2,
                                             const typename O::V& rv_l1,
                                             const typename O::V& radius, const typename O::V& t) {
  using V = typename O::V;
  const V m = O::splat(b.k_corner) + O::splat(b.k_radius) * radius + O::splat(b.k_accel) * (t * t) +
              rv_l1 * t;
  return O::gt(kFarShrink * rel2, m * m) & O::lt(rel2, O::splat(INFINITY));
}

// Everything the first tier needs, as plain numbers.
struct FirstTier {
  double origin[3];
  double frame_v[3];
  double grown_v[3];
  bool same_frame;  // grown_v = frame_v
  bool grown;
  FarBound box;
  FarBound grown_box;
  HorizonBound horizon;
  double ground;
  double window;
};

// One fragment's world state, W lanes at a time (the last fragment repeated past the end).
template <class O>
struct Gathered {
  typename O::V p[3];
  typename O::V v[3];
  typename O::V radius;
};
template <class O, class Index>
[[gnu::always_inline]] inline Gathered<O> gather(const FragmentState* f, Index index) {
  constexpr int W = O::kWidth;
  double buf[7][W];
  for (int k = 0; k < W; ++k) {
    const FragmentState& s = f[index(k)];
    for (int c = 0; c < 3; ++c) {
      buf[c][k] = s.position_m[c];
      buf[3 + c][k] = s.velocity_mps[c];
    }
    buf[6][k] = s.radius_m;
  }
  Gathered<O> g;
  for (int c = 0; c < 3; ++c) {
    g.p[c] = O::load(buf[c]);
    g.v[c] = O::load(buf[3 + c]);
  }
  g.radius = O::load(buf[6]);
  return g;
}

// The first tier's answer for W fragments, with bit k set when fragment k certainly clears the box
// (bit 0 of the pair) and the grown box (bit 1), the interval used, and the positions relative to
// the frame's origin, which the second tier starts from.
template <class O>
struct Far {
  typename O::M box;
  typename O::M grown;
  typename O::V t;
  typename O::V rel[3];
};
template <class O>
[[gnu::always_inline]] inline Far<O> first_tier_test(const FirstTier& p, const Gathered<O>& g) {
  using V = typename O::V;
  V rel[3];
  V rv_l1 = O::splat(0.0);
  V rvg_l1 = O::splat(0.0);
  for (int c = 0; c < 3; ++c) {
    rel[c] = g.p[c] - O::splat(p.origin[c]);
    rv_l1 = rv_l1 + O::abs(g.v[c] - O::splat(p.frame_v[c]));
  }
  if (p.same_frame) {
    rvg_l1 = rv_l1;
  } else {
    for (int c = 0; c < 3; ++c) rvg_l1 = rvg_l1 + O::abs(g.v[c] - O::splat(p.grown_v[c]));
  }
  const V rel2 = rel[0] * rel[0] + rel[1] * rel[1] + rel[2] * rel[2];
  // At least the interval edge-min's solve examines.
  const V t = interval_bound<O>(p.horizon, g.p[1], g.v[1], O::splat(p.ground) + g.radius);
  Far<O> out{stays_far<O>(p.box, rel2, rv_l1, g.radius, t),
             stays_far<O>(p.grown_box, rel2, rvg_l1, g.radius, O::min(O::splat(p.window), t)),
             t,
             {rel[0], rel[1], rel[2]}};
  if (!p.grown) out.grown = O::ge(t, t) | O::lt(t, t);  // all set (t is never NaN)
  return out;
}

// The first tier over fragments [0, n) of f. It lists, without a branch, those not certainly clear
// of both boxes (as base + their index), and returns how many; the largest radius goes to r_max.
// The last group repeats the last fragment in its spare lanes.
template <class O>
[[gnu::always_inline]] inline std::size_t first_tier(const FragmentState* f, std::size_t n,
                                                     const FirstTier& p, std::size_t base,
                                                     std::int32_t* doubt, double* r_max) {
  using V = typename O::V;
  constexpr int W = O::kWidth;
  V r = O::splat(0.0);
  std::size_t doubts = 0;
  for (std::size_t i = 0; i < n; i += W) {
    const Gathered<O> g =
        gather<O>(f, [&](int k) { return std::min(i + static_cast<std::size_t>(k), n - 1); });
    r = O::max(r, g.radius);
    const Far<O> far = first_tier_test<O>(p, g);
    const int settled = O::bits(far.box & far.grown);
    for (int k = 0; k < W; ++k) {
      doubt[doubts] = static_cast<std::int32_t>(base + i + static_cast<std::size_t>(k));
      const bool real = i + static_cast<std::size_t>(k) < n;
      doubts += static_cast<std::size_t>(real && ((settled >> k) & 1) == 0);
    }
  }
  double lanes_r[W];
  std::memcpy(lanes_r, &r, sizeof lanes_r);
  double out = lanes_r[0];
  for (int k = 1; k < W; ++k) out = std::max(out, lanes_r[k]);
  *r_max = out;
  return doubts;
}

std::size_t first_tier_narrow(const FragmentState* f, std::size_t n, const FirstTier& p,
                              std::int32_t* doubt, double* r_max) {
  return first_tier<NarrowOps>(f, n, p, 0, doubt, r_max);
}

// Everything the second tier needs, in lanes of either width.
template <class O>
struct SecondTierOf {
  using V = typename O::V;
  V frame_v[3];
  V grown_v[3];
  // grown_v and frame_v the same bits, so the grown box's velocities are the box's (== would take
  // -0 for +0, and the zero's sign can reach a quotient's).
  bool same_frame;
  V axes[3][3];
  BoxAccelOf<O> acc;
  BoxAccelOf<O> grown_acc;
  V a_l1;
  V window;
  V lo[3];
  V hi[3];
  V glo[3];
  V ghi[3];
  // The grown box's window in pieces (TwoBoxClearance::Boxes::pieces), each piece's start and end,
  // and its box.
  int pieces;
  V piece_t0[TwoBoxClearance::Boxes::kMaxPieces];
  V piece_t1[TwoBoxClearance::Boxes::kMaxPieces];
  BoxAccelOf<O> piece_acc[TwoBoxClearance::Boxes::kMaxPieces];
  V piece_lo[TwoBoxClearance::Boxes::kMaxPieces][3];
  V piece_hi[TwoBoxClearance::Boxes::kMaxPieces][3];
};
using SecondTier = SecondTierOf<NarrowOps>;

// What the second tier takes for a lane's worth of fragments, their positions relative to the
// frame's origin (the first tier's numbers), world velocities and radii, and the first tier's
// answer, each one's interval and which boxes it cleared (a bit each).
template <class O>
struct Doubts {
  typename O::V rel[3];
  typename O::V v[3];
  typename O::V radius;
  typename O::V t;
  int box;
  int grown;
};
template <class O>
[[gnu::always_inline]] inline Doubts<O> doubts_of(const Gathered<O>& g, const Far<O>& far) {
  return {{far.rel[0], far.rel[1], far.rel[2]},
          {g.v[0], g.v[1], g.v[2]},
          g.radius,
          far.t,
          O::bits(far.box),
          O::bits(far.grown)};
}

// Which lanes certainly clear the box and the grown box, a bit each.
struct Verdict {
  int box;
  int grown;
};

// Where the second tier writes its answers. Raw pointers, as a store through a char may alias
// anything, the vectors' own pointers included.
struct Answers {
  char* clears;
  char* grown_clears;
  std::int32_t* unsettled;
  std::size_t unsettled_count;
};

// The grown box piece by piece, for paths whose whole window left it in doubt (d, w their
// coordinates and velocities in the grown box's frame, tg each one's window), set where every
// piece's box is missed over the piece's part of [0, tg]. Each piece's test starts at its own start
// time, so the path is moved there first (rounding far inside the box test's margin). The lanes in
// `settled` are answered too but not wanted, so the pieces stop once every other lane has failed
// one, and a piece that is past for all the others is not tested.
template <class O>
[[gnu::always_inline]] inline typename O::M grown_by_pieces(const SecondTierOf<O>& q,
                                                            const typename O::V (&d)[3],
                                                            const typename O::V (&w)[3],
                                                            typename O::V radius, typename O::V tg,
                                                            int settled) {
  using V = typename O::V;
  constexpr int all = (1 << O::kWidth) - 1;
  const V zero{};
  typename O::M clear = O::eq(zero, zero);
  int open = ~settled & all;  // the wanted lanes every piece so far has cleared
  for (int j = 0; j < q.pieces; ++j) {
    const V t0 = q.piece_t0[j];
    const V t1 = O::min(tg, q.piece_t1[j]);
    // The path's window ends before this piece (strictly, as a window ending at a piece's start
    // still has that instant to test, and a window of 0 s its one instant in the first piece).
    const typename O::M past = O::lt(t1, t0);
    const int skip = (~open | O::bits(past)) & all;
    if (skip == all) continue;
    const BoxAccelOf<O>& acc = q.piece_acc[j];
    V dj[3];
    V wj[3];
    for (int c = 0; c < 3; ++c) {
      dj[c] = at(d[c], w[c], acc.a[c], t0);
      wj[c] = w[c] + 2.0 * acc.a[c] * t0;
    }
    const V span = O::max(t1 - t0, zero);
    const V reach = q.a_l1 * (span * span) + acc.reach_m;
    clear = clear & (past | box_clear<O>(dj, wj, acc, q.piece_lo[j], q.piece_hi[j], radius, span,
                                         reach, skip));
    open &= O::bits(clear);
    if (open == 0) break;
  }
  return clear;
}

// A lane's worth of paths in the grown box's frame for its pieces, with coordinates, velocities,
// radii and windows.
template <class O>
struct GrownPaths {
  typename O::V d[3];
  typename O::V w[3];
  typename O::V radius;
  typename O::V tg;
};

// The second tier for a lane's worth of fragments, all but the grown box's pieces. It runs the box
// tests in the frame's axes, each over the fragment's interval (the first tier's bound on it) and,
// for the grown box, the window within it, for the lanes the first tier left in doubt of each. Each
// lane's answer is its own, whatever its neighbours. Where the grown box is left in doubt, `grown`
// gets the paths for the pieces.
template <class O>
[[gnu::always_inline]] inline Verdict second_tier_whole(const SecondTierOf<O>& q,
                                                        const Doubts<O>& in, GrownPaths<O>& grown) {
  using V = typename O::V;
  constexpr int all = (1 << O::kWidth) - 1;
  const V rv[3] = {in.v[0] - q.frame_v[0], in.v[1] - q.frame_v[1], in.v[2] - q.frame_v[2]};
  V d[3];
  V w[3];
  for (int c = 0; c < 3; ++c) {
    d[c] = dot(in.rel, q.axes[c]);
    w[c] = dot(rv, q.axes[c]);
  }
  const V t = in.t;
  Verdict out{in.box, in.grown};
  if (out.box != all) {
    const V reach = q.a_l1 * (t * t) + q.acc.reach_m;
    out.box |= O::bits(box_clear<O>(d, w, q.acc, q.lo, q.hi, in.radius, t, reach, out.box));
  }
  if (out.grown != all) {
    V wg[3] = {w[0], w[1], w[2]};
    if (!q.same_frame) {
      const V rvg[3] = {in.v[0] - q.grown_v[0], in.v[1] - q.grown_v[1], in.v[2] - q.grown_v[2]};
      for (int c = 0; c < 3; ++c) wg[c] = dot(rvg, q.axes[c]);
    }
    const V tg = O::min(q.window, t);
    const V reach = q.a_l1 * (tg * tg) + q.grown_acc.reach_m;
    out.grown |=
        O::bits(box_clear<O>(d, wg, q.grown_acc, q.glo, q.ghi, in.radius, tg, reach, out.grown));
    grown = {{d[0], d[1], d[2]}, {wg[0], wg[1], wg[2]}, in.radius, tg};
  }
  return out;
}

// The whole second tier, pieces included.
template <class O>
[[gnu::always_inline]] inline Verdict second_tier(const SecondTierOf<O>& q, const Doubts<O>& in) {
  constexpr int all = (1 << O::kWidth) - 1;
  GrownPaths<O> g;
  Verdict out = second_tier_whole<O>(q, in, g);
  if (out.grown != all && q.pieces > 0) {
    out.grown |= O::bits(grown_by_pieces<O>(q, g.d, g.w, g.radius, g.tg, out.grown));
  }
  return out;
}

// The second tier's constants for a run's boxes.
SecondTier second_tier_constants(const TwoBoxClearance::Boxes& boxes) {
  const BoxFrame& frame = boxes.frame;
  const Eigen::Vector3d grown_lo = boxes.lo_m - boxes.grow_lo_m;
  const Eigen::Vector3d grown_hi = boxes.hi_m + boxes.grow_hi_m;
  SecondTier q;
  broadcast3(frame.velocity_mps, q.frame_v);
  broadcast3(boxes.grown_velocity_mps, q.grown_v);
  q.same_frame = std::memcmp(frame.velocity_mps.data(), boxes.grown_velocity_mps.data(),
                             3 * sizeof(double)) == 0;
  for (int c = 0; c < 3; ++c) broadcast3(frame.axes[c], q.axes[c]);
  q.acc = box_accel(boxes.a_mps2, boxes.lo_m, boxes.hi_m, 0.0);
  q.grown_acc = box_accel(boxes.a_mps2, grown_lo, grown_hi, 0.0);
  q.a_l1 = lanes::broadcast(boxes.a_mps2.lpNorm<1>());
  q.window = lanes::broadcast(boxes.window_s);
  broadcast3(boxes.lo_m, q.lo);
  broadcast3(boxes.hi_m, q.hi);
  broadcast3(grown_lo, q.glo);
  broadcast3(grown_hi, q.ghi);
  q.pieces = boxes.grown ? std::clamp(boxes.pieces, 0, TwoBoxClearance::Boxes::kMaxPieces) : 0;
  for (int j = 0; j < q.pieces; ++j) {
    const auto u = static_cast<std::size_t>(j);
    const Eigen::Vector3d piece_lo = boxes.lo_m - boxes.piece_grow_lo_m[u];
    const Eigen::Vector3d piece_hi = boxes.hi_m + boxes.piece_grow_hi_m[u];
    q.piece_t0[j] = lanes::broadcast(boxes.window_s * j / q.pieces);
    q.piece_t1[j] = lanes::broadcast(boxes.window_s * (j + 1) / q.pieces);
    q.piece_acc[j] = box_accel(boxes.a_mps2, piece_lo, piece_hi, 0.0);
    broadcast3(piece_lo, q.piece_lo[j]);
    broadcast3(piece_hi, q.piece_hi[j]);
  }
  return q;
}

// Those constants, built when first asked for.
struct LazySecondTier {
  const TwoBoxClearance::Boxes* boxes;
  std::optional<SecondTier> q;
  const SecondTier& get() {
    if (!q) q.emplace(second_tier_constants(*boxes));
    return *q;
  }
};

// The second tier over the fragments the first left in doubt (ascending), two at a time.
void second_tier_over(const FragmentState* f, const FirstTier& p, LazySecondTier& lazy,
                      const std::int32_t* doubt, std::size_t doubts, Answers& out) {
  if (doubts == 0) return;
  const SecondTier& q = lazy.get();
  for (std::size_t j = 0; j < doubts; j += lanes::kWidth) {
    const std::size_t j1 = std::min(j + 1, doubts - 1);
    const std::size_t index[2] = {static_cast<std::size_t>(doubt[j]),
                                  static_cast<std::size_t>(doubt[j1])};
    const Gathered<NarrowOps> g = gather<NarrowOps>(f, [&](int k) { return index[k]; });
    const Verdict s = second_tier<NarrowOps>(q, doubts_of(g, first_tier_test<NarrowOps>(p, g)));
    const int settled = s.box & s.grown;
    for (int k = 0; k < (j1 > j ? 2 : 1); ++k) {
      const std::size_t i = index[k];
      out.clears[i] = static_cast<char>((s.box >> k) & 1);
      out.grown_clears[i] = static_cast<char>((s.grown >> k) & 1);
      out.unsettled[out.unsettled_count] = static_cast<std::int32_t>(i);
      out.unsettled_count += static_cast<std::size_t>(1 - ((settled >> k) & 1));
    }
  }
}

// The rows of four the wide pass keeps of a group in doubt (TwoBoxClearance::WorkSpace::kept), the
// positions relative to the origin, the velocities, the radii and the intervals.
constexpr std::size_t kKeptRows = 8;

// The lanes the grown box's pieces are left to test, packed, as the pieces are the costliest stage
// and most groups that reach them do so for one or two lanes. Packed, they run over full groups of
// four, each lane with the same numbers as in its own group. Lane l of row r is at
// rows[r * stride + l] (the rows GrownPaths' numbers in order), its group and place in it
// (4 group + lane) at group_lane[l].
constexpr std::size_t kPieceRows = 8;
struct PieceLanes {
  double* rows;
  std::size_t stride;
  std::int32_t* group_lane;
  std::size_t count;
};

// The wide pass's work arrays for n fragments, kept rows for n / 4 groups plus 3 doubles to align
// them on 32 bytes (a row of four in one cache line); a packed row has room for every lane of the
// groups and the spare lanes of its last store of four.
constexpr std::size_t kept_doubles(std::size_t n) {
  return 4 * kKeptRows * (n / 4 + 1) + 3;
}
constexpr std::size_t piece_stride(std::size_t n) {
  return n + 4;
}

#if defined(FRAGSIM_WIDE_LANES)
// Four fragments' states when each one's position and velocity are six consecutive doubles
// (`packed`), read by one load of four and one of two per fragment, transposed, instead of a load
// per number.
[[gnu::target("avx2"), gnu::always_inline]] inline Gathered<WideOps> gather_packed(
    const FragmentState* f) {
  const double* q[4] = {f[0].position_m.data(), f[1].position_m.data(), f[2].position_m.data(),
                        f[3].position_m.data()};
  const __m256d a0 = _mm256_loadu_pd(q[0]);  // px py pz vx
  const __m256d a1 = _mm256_loadu_pd(q[1]);
  const __m256d a2 = _mm256_loadu_pd(q[2]);
  const __m256d a3 = _mm256_loadu_pd(q[3]);
  const __m256d lo01 = _mm256_unpacklo_pd(a0, a1);  // px0 px1 pz0 pz1
  const __m256d hi01 = _mm256_unpackhi_pd(a0, a1);  // py0 py1 vx0 vx1
  const __m256d lo23 = _mm256_unpacklo_pd(a2, a3);
  const __m256d hi23 = _mm256_unpackhi_pd(a2, a3);
  const __m256d b02 = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(q[0] + 4)),
                                           _mm_loadu_pd(q[2] + 4), 1);  // vy0 vz0 vy2 vz2
  const __m256d b13 = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(q[1] + 4)),
                                           _mm_loadu_pd(q[3] + 4), 1);
  Gathered<WideOps> g;
  g.p[0] = reinterpret_cast<Wide>(_mm256_permute2f128_pd(lo01, lo23, 0x20));
  g.p[1] = reinterpret_cast<Wide>(_mm256_permute2f128_pd(hi01, hi23, 0x20));
  g.p[2] = reinterpret_cast<Wide>(_mm256_permute2f128_pd(lo01, lo23, 0x31));
  g.v[0] = reinterpret_cast<Wide>(_mm256_permute2f128_pd(hi01, hi23, 0x31));
  g.v[1] = reinterpret_cast<Wide>(_mm256_unpacklo_pd(b02, b13));
  g.v[2] = reinterpret_cast<Wide>(_mm256_unpackhi_pd(b02, b13));
  g.radius = Wide{f[0].radius_m, f[1].radius_m, f[2].radius_m, f[3].radius_m};
  return g;
}

// The second tier's constants, four lanes wide (each is the same number in every lane).
[[gnu::target("avx2"), gnu::always_inline]] inline Wide widen(Lanes x) {
  return WideOps::splat(x[0]);
}
template <int N>
[[gnu::target("avx2"), gnu::always_inline]] inline void widen(const Lanes (&x)[N], Wide (&out)[N]) {
  for (int c = 0; c < N; ++c) out[c] = widen(x[c]);
}
[[gnu::target("avx2"), gnu::always_inline]] inline BoxAccelOf<WideOps> widen(const BoxAccel& a) {
  BoxAccelOf<WideOps> w;
  widen(a.a, w.a);
  widen(a.minus_inv_2a, w.minus_inv_2a);
  w.inv_a_z = widen(a.inv_a_z);
  for (int c = 0; c < 3; ++c) w.curved[c] = a.curved[c];
  w.reach_m = widen(a.reach_m);
  return w;
}
[[gnu::target("avx2"), gnu::always_inline]] inline SecondTierOf<WideOps> widen(
    const SecondTier& q) {
  SecondTierOf<WideOps> w;
  widen(q.frame_v, w.frame_v);
  widen(q.grown_v, w.grown_v);
  w.same_frame = q.same_frame;
  for (int c = 0; c < 3; ++c) widen(q.axes[c], w.axes[c]);
  w.acc = widen(q.acc);
  w.grown_acc = widen(q.grown_acc);
  w.a_l1 = widen(q.a_l1);
  w.window = widen(q.window);
  widen(q.lo, w.lo);
  widen(q.hi, w.hi);
  widen(q.glo, w.glo);
  widen(q.ghi, w.ghi);
  w.pieces = q.pieces;
  for (int j = 0; j < q.pieces; ++j) {
    w.piece_t0[j] = widen(q.piece_t0[j]);
    w.piece_t1[j] = widen(q.piece_t1[j]);
    w.piece_acc[j] = widen(q.piece_acc[j]);
    widen(q.piece_lo[j], w.piece_lo[j]);
    widen(q.piece_hi[j], w.piece_hi[j]);
  }
  return w;
}

// Four fragments' states from f.
[[gnu::target("avx2"), gnu::always_inline]] inline Gathered<WideOps> load_four(
    const FragmentState* f, bool packed) {
  return packed ? gather_packed(f) : gather<WideOps>(f, [](int k) { return k; });
}

// What the first loop keeps of a group for the second, kKeptRows rows of four, in two parts. The
// rows the first tier's test does not need once it has begun (x and z of the positions relative to
// the origin and of the velocities) are stored before the test, whether the group turns out in
// doubt or not, as held until that is known they would be live across the test and spilled (the
// flight's rejection about 4% slower). The rest, live to the end anyway, are stored only for a
// group in doubt, by keep_late.
[[gnu::target("avx2"), gnu::always_inline]] inline void keep_early(const FirstTier& p,
                                                                   const Gathered<WideOps>& g,
                                                                   double* kept) {
  for (int c = 0; c < 3; c += 2) {
    const Wide rel = g.p[c] - WideOps::splat(p.origin[c]);  // as first_tier_test's
    _mm256_storeu_pd(kept + 4 * c, reinterpret_cast<__m256d>(rel));
    _mm256_storeu_pd(kept + 4 * (3 + c), reinterpret_cast<__m256d>(g.v[c]));
  }
}
[[gnu::target("avx2"), gnu::always_inline]] inline void keep_late(const Gathered<WideOps>& g,
                                                                  const Far<WideOps>& far,
                                                                  double* kept) {
  _mm256_storeu_pd(kept + 4 * 1, reinterpret_cast<__m256d>(far.rel[1]));
  _mm256_storeu_pd(kept + 4 * 4, reinterpret_cast<__m256d>(g.v[1]));
  _mm256_storeu_pd(kept + 4 * 6, reinterpret_cast<__m256d>(g.radius));
  _mm256_storeu_pd(kept + 4 * 7, reinterpret_cast<__m256d>(far.t));
}
[[gnu::target("avx2"), gnu::always_inline]] inline Doubts<WideOps> kept_doubts(const double* kept,
                                                                               int bits) {
  Doubts<WideOps> in;
  for (int c = 0; c < 3; ++c) {
    in.rel[c] = WideOps::load(kept + 4 * c);
    in.v[c] = WideOps::load(kept + 4 * (3 + c));
  }
  in.radius = WideOps::load(kept + 4 * 6);
  in.t = WideOps::load(kept + 4 * 7);
  in.box = bits & 15;
  in.grown = bits >> 4;
  return in;
}

// A group's answers, written whole. The lanes the first tier settled have both flags set, as they
// were, and no unsettled entry. Per pattern of bits the tables hold each lane's flag as a byte
// (clears_ and grown_clears_ are runs of chars), which lanes are set, in order (to list them), and
// the permutation of 32-bit halves that moves those lanes of four doubles to the front, in order.
struct GroupTables {
  alignas(32) std::int32_t to_front[16][8];
  std::int32_t set[16][4];
  std::uint32_t bytes[16];
};
constexpr GroupTables group_tables() {
  GroupTables t{};
  for (int m = 0; m < 16; ++m) {
    int listed = 0;
    for (int k = 0; k < 4; ++k) {
      if (((m >> k) & 1) == 0) continue;
      t.bytes[m] |= std::uint32_t{1} << (8 * k);
      t.to_front[m][2 * listed] = 2 * k;
      t.to_front[m][2 * listed + 1] = 2 * k + 1;
      t.set[m][listed++] = k;
    }
  }
  return t;
}
constexpr GroupTables kGroupTables = group_tables();

// Four entries at `to`, base + each lane of `lanes` in order; returns how many of them count.
// The caller has room for four.
[[gnu::target("avx2"), gnu::always_inline]] inline std::size_t list_lanes(int lanes,
                                                                          std::int32_t base,
                                                                          std::int32_t* to) {
  const __m128i listed =
      _mm_add_epi32(_mm_set1_epi32(base),
                    _mm_loadu_si128(reinterpret_cast<const __m128i*>(kGroupTables.set[lanes])));
  _mm_storeu_si128(reinterpret_cast<__m128i*>(to), listed);
  return static_cast<std::size_t>(__builtin_popcount(static_cast<unsigned>(lanes)));
}

[[gnu::target("avx2"), gnu::always_inline]] inline void write_four(const Verdict& s,
                                                                   std::size_t start,
                                                                   Answers& out) {
  std::memcpy(out.clears + start, &kGroupTables.bytes[s.box], 4);
  std::memcpy(out.grown_clears + start, &kGroupTables.bytes[s.grown], 4);
  // Room for four entries, as at most `start` are listed before this group, which ends within the
  // fragments.
  out.unsettled_count += list_lanes(~(s.box & s.grown) & 15, static_cast<std::int32_t>(start),
                                    out.unsettled + out.unsettled_count);
}

// Appends the lanes of `g` in `lanes` (a bit each) of group `group`. Each row is moved to the front
// by one permutation and stored whole (four doubles), the spare lanes overwritten by the next
// group's or never read. stride >= the lanes appended + 3.
[[gnu::target("avx2"), gnu::always_inline]] inline void put_front(double* at, const Wide& x,
                                                                  __m256i order) {
  const __m256 moved = _mm256_permutevar8x32_ps(reinterpret_cast<__m256>(x), order);
  _mm256_storeu_pd(at, reinterpret_cast<__m256d>(moved));
}
[[gnu::target("avx2"), gnu::always_inline]] inline void pack(const GrownPaths<WideOps>& g,
                                                             int lanes, std::size_t group,
                                                             PieceLanes& to) {
  const __m256i order =
      _mm256_load_si256(reinterpret_cast<const __m256i*>(kGroupTables.to_front[lanes]));
  double* const at = to.rows + to.count;
  for (std::size_t c = 0; c < 3; ++c) {
    put_front(at + c * to.stride, g.d[c], order);
    put_front(at + (3 + c) * to.stride, g.w[c], order);
  }
  put_front(at + 6 * to.stride, g.radius, order);
  put_front(at + 7 * to.stride, g.tg, order);
  to.count += list_lanes(lanes, static_cast<std::int32_t>(4 * group), to.group_lane + to.count);
}

// The pieces over the packed lanes, four at a time; each lane cleared sets its grown bit (bit 4 +
// lane) in its group's verdict. The last group's spare lanes are garbage, answered but ignored.
[[gnu::target("avx2"), gnu::always_inline]] inline void pieces_over(const SecondTierOf<WideOps>& q,
                                                                    const PieceLanes& lanes,
                                                                    std::int32_t* verdicts) {
  using O = WideOps;
  for (std::size_t j = 0; j < lanes.count; j += O::kWidth) {
    const double* const at = lanes.rows + j;
    GrownPaths<O> g;
    for (std::size_t c = 0; c < 3; ++c) {
      g.d[c] = O::load(at + c * lanes.stride);
      g.w[c] = O::load(at + (3 + c) * lanes.stride);
    }
    g.radius = O::load(at + 6 * lanes.stride);
    g.tg = O::load(at + 7 * lanes.stride);
    const int live = static_cast<int>(std::min<std::size_t>(lanes.count - j, O::kWidth));
    const int spare = 15 & ~((1 << live) - 1);
    const int clear = O::bits(grown_by_pieces<O>(q, g.d, g.w, g.radius, g.tg, spare));
    for (int k = 0; k < live; ++k) {
      const std::int32_t place = lanes.group_lane[j + static_cast<std::size_t>(k)];
      verdicts[place >> 2] |= ((clear >> k) & 1) << (4 + (place & 3));
    }
  }
}

// The first loop over the whole groups of four (the mask's bits by AVX's own instruction, which
// only code compiled for AVX may use). It lists the groups with a fragment in doubt in `groups` and
// returns how many; the largest radius goes to r_max, the count of doubts to `doubts`. With kKeep
// it also keeps what the second loop needs of each group (`kept`, kKeptRows rows of four, and its
// bits in `verdicts`), for flying debris, nearly all in doubt; without, the loop is as lean as
// settled debris (none in doubt) wants it, and the second loop gathers and tests its few groups
// again (the same numbers). `kept` is restrict, or its stores could alias `p` and the loop would
// load p's numbers for each group.
template <bool kKeep>
[[gnu::target("avx2"), gnu::always_inline]] inline std::size_t first_loop(
    const FragmentState* f, std::size_t n, const FirstTier& p, bool packed, std::int32_t* groups,
    std::int32_t* verdicts, double* __restrict kept, Wide& r_max, std::size_t& doubts) {
  using O = WideOps;
  // Locals, which no store through `kept` or `groups` can alias.
  O::V r = r_max;
  std::size_t counted = 0;
  std::size_t open_groups = 0;
  for (std::size_t i = 0; i + O::kWidth <= n; i += O::kWidth) {
    const Gathered<O> g = load_four(f + i, packed);
    r = O::max(r, g.radius);
    double* const slot = kept + 4 * kKeptRows * open_groups;
    if constexpr (kKeep) keep_early(p, g, slot);
    const Far<O> far = first_tier_test<O>(p, g);
    if constexpr (kKeep) {
      const int box = _mm256_movemask_pd(reinterpret_cast<__m256d>(far.box.bits));
      const int grown = _mm256_movemask_pd(reinterpret_cast<__m256d>(far.grown.bits));
      const int open = ~(box & grown) & 15;
      counted += static_cast<std::size_t>(__builtin_popcount(static_cast<unsigned>(open)));
      if (open == 0) continue;
      keep_late(g, far, slot);
      verdicts[open_groups] = box | grown << 4;
      groups[open_groups] = static_cast<std::int32_t>(i);
      ++open_groups;
    } else {
      const int open =
          ~_mm256_movemask_pd(reinterpret_cast<__m256d>((far.box & far.grown).bits)) & 15;
      counted += static_cast<std::size_t>(__builtin_popcount(static_cast<unsigned>(open)));
      groups[open_groups] = static_cast<std::int32_t>(i);
      open_groups += static_cast<std::size_t>(open != 0);
    }
  }
  r_max = r;
  doubts += counted;
  return open_groups;
}

// Out of line, as inlined beside first_loop<false> and the second loop its registers come out worse
// (about 5% more instructions over the flight); first_loop<false> stays inlined.
[[gnu::target("avx2"), gnu::noinline]] std::size_t keeping_first_loop(
    const FragmentState* f, std::size_t n, const FirstTier& p, bool packed, std::int32_t* groups,
    std::int32_t* verdicts, double* __restrict kept, Wide& r_max, std::size_t& doubts) {
  return first_loop<true>(f, n, p, packed, groups, verdicts, kept, r_max, doubts);
}

// What first_loop<true> keeps of the groups first_loop<false> listed, gathered and tested again
// (the same numbers).
[[gnu::target("avx2"), gnu::always_inline]] inline void keep_again(
    const FragmentState* f, const FirstTier& p, bool packed, const std::int32_t* groups,
    std::size_t open_groups, std::int32_t* verdicts, double* kept) {
  using O = WideOps;
  for (std::size_t k = 0; k < open_groups; ++k) {
    double* const slot = kept + 4 * kKeptRows * k;
    const Gathered<O> g = load_four(f + groups[k], packed);
    keep_early(p, g, slot);
    const Far<O> far = first_tier_test<O>(p, g);
    keep_late(g, far, slot);
    verdicts[k] = O::bits(far.box) | O::bits(far.grown) << 4;
  }
}

// The whole groups of four through first_loop, then those with a fragment in doubt through the
// second tier four lanes at once. Two loops, so that the first, which settled debris runs through
// with nothing in doubt, stays small, its constants in registers. The second leaves the grown box's
// pieces to the lanes it packs (`pieces`), and the answers are written once those are done. *keep
// says whether the first loop keeps what the second needs, and is set for the next run to whether
// this one left more than a few groups in doubt (a guess at the next, which changes how fast a run
// is, never what it answers). The rest go two at a time through the first tier, their doubts listed
// in `doubt` for second_tier_over; the count of those is returned, every doubt's in *doubts.
// `groups`, `verdicts` and `kept` have room for n / 4 groups.
[[gnu::target("avx2")]] std::size_t both_tiers_wide(
    const FragmentState* f, std::size_t n, const FirstTier& p, bool packed, LazySecondTier& q,
    Answers& out, std::int32_t* groups, std::int32_t* verdicts, double* kept, PieceLanes pieces,
    bool* keep, std::int32_t* doubt, double* r_max, std::size_t* doubts) {
  using O = WideOps;
  O::V r = O::splat(0.0);
  std::size_t wide_doubts = 0;
  const bool kept_rows = *keep;
  const std::size_t open_groups =
      kept_rows ? keeping_first_loop(f, n, p, packed, groups, verdicts, kept, r, wide_doubts)
                : first_loop<false>(f, n, p, packed, groups, verdicts, kept, r, wide_doubts);
  const std::size_t i = n / O::kWidth * O::kWidth;
  // Keeping costs settled debris about 7% of the first loop's instructions; not keeping costs a
  // group in doubt its gathering and first tier again, about a third of its second tier's.
  *keep = 64 * open_groups > n / O::kWidth;
  if (open_groups > 0) {
    const SecondTierOf<O> wq = widen(q.get());
    if (!kept_rows) keep_again(f, p, packed, groups, open_groups, verdicts, kept);
    for (std::size_t k = 0; k < open_groups; ++k) {
      const Doubts<O> in = kept_doubts(kept + 4 * kKeptRows * k, verdicts[k]);
      GrownPaths<O> g;
      const Verdict s = second_tier_whole<O>(wq, in, g);
      if (s.grown != 15 && wq.pieces > 0) pack(g, ~s.grown & 15, k, pieces);
      verdicts[k] = s.box | s.grown << 4;
    }
    pieces_over(wq, pieces, verdicts);
    // A copy the stores through char cannot alias, so its pointers stay in registers.
    Answers to = out;
    for (std::size_t k = 0; k < open_groups; ++k) {
      const Verdict s{verdicts[k] & 15, verdicts[k] >> 4};
      write_four(s, static_cast<std::size_t>(groups[k]), to);
    }
    out.unsettled_count = to.unsettled_count;
  }
  double rest = 0.0;
  std::size_t tail_doubts = 0;
  if (i < n) tail_doubts = first_tier<NarrowOps>(f + i, n - i, p, i, doubt, &rest);
  double lanes_r[O::kWidth];
  std::memcpy(lanes_r, &r, sizeof lanes_r);
  double out_r = rest;
  for (const double x : lanes_r) out_r = std::max(out_r, x);
  *r_max = out_r;
  *doubts = wide_doubts + tail_doubts;
  return tail_doubts;
}
#endif
// -Wpsabi stays off to the end of the file, as the templates above are instantiated there.

}  // namespace

double interval_bound_s(double y_m, double vy_mps, double half_gy_mps2, double ground_m,
                        double cap_s, double floor_s) {
  const Lanes t =
      interval_bound<NarrowOps>(horizon_bound(half_gy_mps2, cap_s, floor_s), lanes::broadcast(y_m),
                                lanes::broadcast(vy_mps), lanes::broadcast(ground_m));
  return t[0];
}

TwoBoxClearance::TwoBoxClearance(MemoryResource* mem) : mem_(mem) {
#if defined(FRAGSIM_WIDE_LANES)
  wide_ = __builtin_cpu_supports("avx2");
#endif
}

void TwoBoxClearance::use_wide_lanes(bool wide) {
#if defined(FRAGSIM_WIDE_LANES)
  wide_ = wide && __builtin_cpu_supports("avx2");
#else
  (void)wide;
#endif
}

// Only ever grown, as nothing in them carries over from one pass to the next, and a resize in each
// pass would write them whole on the first after reserve().
void TwoBoxClearance::WorkSpace::size_for(std::size_t n) {
  const auto at_least = [](auto& v, std::size_t size) {
    if (v.size() < size) v.resize(size);
  };
  at_least(doubt, n + 4);
  at_least(groups, n / 4 + 1);
  at_least(kept, kept_doubles(n));
  at_least(verdicts, n / 4 + 1);
  at_least(piece_rows, kPieceRows * piece_stride(n));
  at_least(piece_lanes, piece_stride(n));
}

void TwoBoxClearance::WorkSpace::reserve(std::size_t n) {
  reserve_touched(doubt, n + 4);
  reserve_touched(groups, n / 4 + 1);
  size_for(n);
}

void TwoBoxClearance::reserve(std::size_t n) {
  reserve_touched(clears_, n);
  reserve_touched(grown_clears_, n);
  whole_.reserve(n);
  reserve_touched(unsettled_, n);
  // Kept at its largest size like the flags, as reserve() runs before every controller step.
  const std::size_t chunks = (n + kChunk - 1) / kChunk;
  if (chunks_.size() < chunks) chunks_.resize(chunks);
}

void TwoBoxClearance::set_workers(int workers) {
  const auto wanted = static_cast<std::size_t>(std::max(workers, 1));
  workers_.reserve(wanted);
  while (workers_.size() < wanted) {
    // Made whole before it joins, as an allocation that fails half way must not leave a work space
    // without its unsettled list for the next run to write through.
    WorkSpace w(mem_);
    w.reserve(static_cast<std::size_t>(kChunk));
    w.unsettled.resize(static_cast<std::size_t>(kChunk));
    workers_.push_back(std::move(w));  // within the reserve, so no allocation and no throw
  }
}

namespace {

// Everything the first tier needs for a run's boxes.
FirstTier first_tier_constants(const TwoBoxClearance::Boxes& boxes) {
  const BoxFrame& frame = boxes.frame;
  const Eigen::Vector3d grown_lo = boxes.lo_m - boxes.grow_lo_m;
  const Eigen::Vector3d grown_hi = boxes.hi_m + boxes.grow_hi_m;
  const double k = inverse_sigma_bound(frame.axes);
  FirstTier p;
  for (int c = 0; c < 3; ++c) {
    p.origin[c] = frame.origin_m[c];
    p.frame_v[c] = frame.velocity_mps[c];
    p.grown_v[c] = boxes.grown_velocity_mps[c];
  }
  p.same_frame = boxes.grown_velocity_mps == frame.velocity_mps;
  p.grown = boxes.grown;
  p.box = far_bound(k, boxes.lo_m, boxes.hi_m, boxes.a_mps2);
  p.grown_box = far_bound(k, grown_lo, grown_hi, boxes.a_mps2);
  p.horizon = horizon_bound(boxes.half_gy_mps2, boxes.cap_s, boxes.floor_s);
  p.ground = boxes.ground_m;
  p.window = boxes.window_s;
  return p;
}

// Both tiers over fragments [0, n) of f (n > 0), in work space w, the first tier over every
// fragment and the second (second_tier_whole, then the pieces) over those it leaves in doubt. The
// flags and the unsettled list go to `out`, indices from f; the largest radius to r_max, the first
// tier's count of doubts to `doubts`.
void both_tiers(const FragmentState* f, std::size_t n, const FirstTier& p,
                const TwoBoxClearance::Boxes& boxes, [[maybe_unused]] bool wide,
                TwoBoxClearance::WorkSpace& w, Answers& out, double* r_max, std::size_t* doubts) {
  // The second tier's constants, built at its first fragment, since in most steps, once the debris
  // has settled, the first tier leaves none.
  LazySecondTier q{&boxes, {}};
  std::int32_t* const doubt = w.doubt.data();
  std::size_t listed = 0;  // doubts listed in `doubt` for second_tier_over
#if defined(FRAGSIM_WIDE_LANES)
  if (wide) {
    const bool packed = f[0].velocity_mps.data() == f[0].position_m.data() + 3;
    void* kept = w.kept.data();
    std::size_t room = kept_doubles(n) * sizeof(double);
    std::align(32, room - 3 * sizeof(double), kept, room);
    listed = both_tiers_wide(
        f, n, p, packed, q, out, w.groups.data(), w.verdicts.data(), static_cast<double*>(kept),
        PieceLanes{w.piece_rows.data(), piece_stride(n), w.piece_lanes.data(), 0}, &w.keep_rows,
        doubt, r_max, doubts);
  } else {
    listed = first_tier_narrow(f, n, p, doubt, r_max);
    *doubts = listed;
  }
#else
  listed = first_tier_narrow(f, n, p, doubt, r_max);
  *doubts = listed;
#endif
  second_tier_over(f, p, q, doubt, listed, out);
}

}  // namespace

void TwoBoxClearance::start_run(std::size_t n) {
  size_ = n;
  clears_.assign(n, 1);
  grown_clears_.assign(n, 1);
  unsettled_.resize(n);
  unsettled_count_ = 0;
  doubts_ = 0;
  max_radius_m_ = 0.0;
}

void TwoBoxClearance::run(std::span<const FragmentState> fragments, const Boxes& boxes) {
  const std::size_t n = fragments.size();
  start_run(n);
  whole_.size_for(n);
  if (n == 0) return;
  const FirstTier p = first_tier_constants(boxes);
  Answers out{clears_.data(), grown_clears_.data(), unsettled_.data(), 0};
  both_tiers(fragments.data(), n, p, boxes, wide_, whole_, out, &max_radius_m_, &doubts_);
  unsettled_count_ = out.unsettled_count;
}

void TwoBoxClearance::join_chunks(std::size_t chunks) {
  for (std::size_t c = 0; c < chunks; ++c) {
    const ChunkResult& result = chunks_[c];
    const auto from = unsettled_.begin() + static_cast<std::ptrdiff_t>(c * kChunk);
    // Moved toward the front (never past its own start), an overlap std::copy allows.
    std::copy(from, from + static_cast<std::ptrdiff_t>(result.unsettled),
              unsettled_.begin() + static_cast<std::ptrdiff_t>(unsettled_count_));
    unsettled_count_ += result.unsettled;
    doubts_ += result.doubts;
    // The largest of the chunks' largest is the run's (max is exact, whatever the order).
    max_radius_m_ = std::max(max_radius_m_, result.max_radius_m);
  }
}

void TwoBoxClearance::run(std::span<const FragmentState> fragments, const Boxes& boxes,
                          const ParallelFor* parallel) {
  const std::size_t n = fragments.size();
  start_run(n);
  if (n == 0) return;
  set_workers(parallel != nullptr ? parallel->worker_count() : 1);  // done once by the caller
  const std::size_t chunks = (n + kChunk - 1) / kChunk;
  if (chunks_.size() < chunks) chunks_.resize(chunks);  // done by reserve(n) before
  const FirstTier p = first_tier_constants(boxes);
  // Chunk c on a worker writes its flags in place, its unsettled fragments to its own slice of the
  // run's list (as indices over all the fragments), and the rest to its own ChunkResult.
  const auto run_chunks = [&](std::int32_t first, std::int32_t end, std::uint32_t worker) {
    WorkSpace& w = workers_[worker];
    for (auto c = static_cast<std::size_t>(first); c < static_cast<std::size_t>(end); ++c) {
      const std::size_t begin = c * static_cast<std::size_t>(kChunk);
      const std::size_t count = std::min(n - begin, static_cast<std::size_t>(kChunk));
      Answers out{clears_.data() + begin, grown_clears_.data() + begin, w.unsettled.data(), 0};
      ChunkResult& result = chunks_[c];
      both_tiers(fragments.data() + begin, count, p, boxes, wide_, w, out, &result.max_radius_m,
                 &result.doubts);
      for (std::size_t k = 0; k < out.unsettled_count; ++k) {
        unsettled_[begin + k] = w.unsettled[k] + static_cast<std::int32_t>(begin);
      }
      result.unsettled = out.unsettled_count;
    }
  };
  for_ranges(parallel, static_cast<std::int32_t>(chunks), 1, run_chunks);
  join_chunks(chunks);
}

}  // namespace fragsim
