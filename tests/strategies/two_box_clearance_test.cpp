// edge-min's cheap rejection (two_box_clearance.hpp) must be conservative: whatever it calls
// clear of the protected or the grown box, the exact answer calls clear too, over the fragment's
// own look-ahead. Hand cases, then random fragments (fixed seeds) in a moving, rotated frame; and
// the wide lanes, the narrow ones and the chunked runs must answer alike.

#include "control/strategies/two_box_clearance.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "control/strategies/edge_min_strategy.hpp"
#include "support/random_paths.hpp"

namespace fragsim {
namespace {

using test::enters_box;
using test::random_box_path;
using test::random_unit;

const Eigen::Vector3d kG(0.0, -9.81, 0.0);
const Eigen::Vector3d kLo(-0.3, -0.25, -0.2);
const Eigen::Vector3d kHi(0.3, 0.25, 0.25);

constexpr double kStep = 1.0 / 60.0;

// edge-min's own look-ahead for a path: until it comes down through the ground, within [floor,
// cap].
double own_interval(double y, double vy, double half_gy, double ground, double cap, double floor) {
  return std::max(std::min(EdgeMinStrategy::time_to_ground_s(y, vy, half_gy, ground), cap), floor);
}

TEST(TwoBoxClearance, IntervalBoundCoversEdgeMinsLookAhead) {
  const double a = -4.905;
  // At rest on the ground, or sunk into it by a contact's softness: one step.
  EXPECT_EQ(interval_bound_s(0.0, 0.0, a, 0.0, 3.0, kStep), kStep);
  EXPECT_EQ(interval_bound_s(-1e-4, 0.0, a, 0.0, 3.0, kStep), kStep);
  EXPECT_EQ(interval_bound_s(-1e-4, -0.2, a, 0.0, 3.0, kStep), kStep);
  // Dropped from 4.905 * 0.5^2 m: 0.5 s to the ground; the bound is within its 25%.
  const double drop = interval_bound_s(4.905 * 0.25, 0.0, a, 0.0, 3.0, kStep);
  EXPECT_GE(drop, 0.5);
  EXPECT_LE(drop, 0.5 * 1.25);
  // Thrown up at 4.905 m/s from the ground: back down after 1 s.
  const double up = interval_bound_s(0.0, 4.905, a, 0.0, 3.0, kStep);
  EXPECT_GE(up, 1.0);
  EXPECT_LE(up, 1.25);
  // No ground, no gravity, gravity up: the cap.
  EXPECT_EQ(interval_bound_s(1.0, 0.0, a, -INFINITY, 3.0, kStep), 3.0);
  EXPECT_EQ(interval_bound_s(1.0, 0.0, 0.0, 0.0, 3.0, kStep), 3.0);
  EXPECT_EQ(interval_bound_s(1.0, 0.0, 2.0, 0.0, 3.0, kStep), 3.0);
  EXPECT_EQ(interval_bound_s(NAN, 0.0, a, 0.0, 3.0, kStep), 3.0);

  // Never below edge-min's own look-ahead, on paths from resting to thrown, tiny to huge.
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto signed_log = [&](double lo_exp, double hi_exp) {
    const double m = std::pow(10.0, lo_exp + (hi_exp - lo_exp) * u(rng));
    return u(rng) < 0.5 ? -m : m;
  };
  for (int n = 0; n < 200000; ++n) {
    const double y = u(rng) < 0.2 ? signed_log(-320, 0) : signed_log(-6, 3);
    const double vy =
        u(rng) < 0.1 ? 0.0 : (u(rng) < 0.2 ? signed_log(-320, 160) : signed_log(-6, 2));
    const double ground = u(rng) < 0.1 ? -INFINITY : signed_log(-3, 1);
    const double half_gy = u(rng) < 0.1 ? signed_log(-3, 2) : -0.5 * 9.81;
    const double cap = u(rng) < 0.1 ? INFINITY : 3.0 * u(rng);
    const double own = own_interval(y, vy, half_gy, ground, cap, kStep);
    ASSERT_GE(interval_bound_s(y, vy, half_gy, ground, cap, kStep), own)
        << "y " << y << " vy " << vy << " ground " << ground << " a " << half_gy << " cap " << cap;
  }
}

FragmentState state_at(const Eigen::Vector3d& p, const Eigen::Vector3d& v, double radius) {
  FragmentState f;
  f.position_m = p;
  f.velocity_mps = v;
  f.radius_m = radius;
  return f;
}

// A still frame at the origin with the world's axes, kLo..kHi, no gravity, 3 s.
TwoBoxClearance::Boxes still_boxes() {
  TwoBoxClearance::Boxes b;
  b.lo_m = kLo;
  b.hi_m = kHi;
  b.cap_s = 3.0;
  b.floor_s = kStep;
  b.ground_m = -INFINITY;
  return b;
}

TEST(TwoBoxClearance, HandCasesForTheProtectedBox) {
  TwoBoxClearance c;
  const TwoBoxClearance::Boxes b = still_boxes();
  // Straight at the box; beside it by 1 cm (x face at 0.3 m); 1 cm inside; along the face
  // itself (tangent: it touches).
  const std::vector<FragmentState> f{
      state_at({0.0, 0.0, 10.0}, {0.0, 0.0, -10.0}, 0.0),
      state_at({0.31, 0.0, 10.0}, {0.0, 0.0, -10.0}, 0.0),
      state_at({0.29, 0.0, 10.0}, {0.0, 0.0, -10.0}, 0.0),
      state_at({0.3, 0.0, 10.0}, {0.0, 0.0, -10.0}, 0.0),
      // The same 1 cm beside, for a fragment of radius 5 cm at 0.36 m.
      state_at({0.36, 0.0, 10.0}, {0.0, 0.0, -10.0}, 0.05),
      state_at({0.34, 0.0, 10.0}, {0.0, 0.0, -10.0}, 0.05)};
  c.run(f, b);
  const std::vector<char> want{0, 1, 0, 0, 1, 0};
  for (std::size_t i = 0; i < f.size(); ++i) {
    EXPECT_EQ(c.clears()[i], want[i]) << i;
    EXPECT_EQ(c.grown_clears()[i], 1) << i;  // no grown box
  }
  EXPECT_EQ(std::vector<std::int32_t>(c.unsettled().begin(), c.unsettled().end()),
            (std::vector<std::int32_t>{0, 2, 3, 5}));
  EXPECT_EQ(c.max_radius_m(), 0.05);
}

TEST(TwoBoxClearance, TheFirstTierIsTheBallAroundTheFarthestCorner) {
  // The farthest corner of kLo..kHi is |(0.3, 0.25, 0.25)| = 0.46368 m away: at rest 0.47 m out
  // along x the first tier settles it; at 0.46 m (inside that ball, outside the box) it leaves it
  // to the box test, which clears it. A radius r adds sqrt(3) r.
  TwoBoxClearance c;
  const TwoBoxClearance::Boxes b = still_boxes();
  c.run(std::vector<FragmentState>{state_at({0.47, 0.0, 0.0}, {0.0, 0.0, 0.0}, 0.0)}, b);
  EXPECT_EQ(c.first_tier_doubts(), 0u);
  EXPECT_EQ(c.clears()[0], 1);
  c.run(std::vector<FragmentState>{state_at({0.46, 0.0, 0.0}, {0.0, 0.0, 0.0}, 0.0)}, b);
  EXPECT_EQ(c.first_tier_doubts(), 1u);
  EXPECT_EQ(c.clears()[0], 1);
  c.run(std::vector<FragmentState>{state_at({0.47 + 1.7320508 * 0.1, 0.0, 0.0},
                                            Eigen::Vector3d::Zero(), 0.1)},
        b);
  EXPECT_EQ(c.first_tier_doubts(), 0u);
  c.run(std::vector<FragmentState>{state_at({0.46 + 1.7320508 * 0.1, 0.0, 0.0},
                                            Eigen::Vector3d::Zero(), 0.1)},
        b);
  EXPECT_EQ(c.first_tier_doubts(), 1u);
  // Moving: 0.47 m out plus what 1 m/s (|v|_1) covers in 3 s.
  c.run(std::vector<FragmentState>{state_at({3.48, 0.0, 0.0}, {-1.0, 0.0, 0.0}, 0.0)}, b);
  EXPECT_EQ(c.first_tier_doubts(), 0u);
  c.run(std::vector<FragmentState>{state_at({3.45, 0.0, 0.0}, {-1.0, 0.0, 0.0}, 0.0)}, b);
  EXPECT_EQ(c.first_tier_doubts(), 1u);
  EXPECT_EQ(c.clears()[0], 1);  // after 3 s it is still at 0.45 m, beyond the face
}

TEST(TwoBoxClearance, HandCasesForTheGrownBox) {
  // Grown by 0.1 m (x face at 0.4 m) over 0.2 s, seen from a frame moving at the same velocity.
  TwoBoxClearance c;
  TwoBoxClearance::Boxes b = still_boxes();
  b.grown = true;
  b.grow_lo_m = Eigen::Vector3d::Constant(0.1);
  b.grow_hi_m = Eigen::Vector3d::Constant(0.1);
  b.window_s = 0.2;
  c.run(std::vector<FragmentState>{state_at({0.45, 0.0, 0.0}, Eigen::Vector3d::Zero(), 0.0),
                                   state_at({0.35, 0.0, 0.0}, Eigen::Vector3d::Zero(), 0.0),
                                   // reaches x = 0.4 at 0.2 s: touches the grown box
                                   state_at({0.6, 0.0, 0.0}, {-1.0, 0.0, 0.0}, 0.0),
                                   state_at({0.61, 0.0, 0.0}, {-1.0, 0.0, 0.0}, 0.0)},
        b);
  EXPECT_EQ(c.clears()[0], 1);
  EXPECT_EQ(c.grown_clears()[0], 1);
  EXPECT_EQ(c.clears()[1], 1);
  EXPECT_EQ(c.grown_clears()[1], 0);
  EXPECT_EQ(c.grown_clears()[2], 0);
  EXPECT_EQ(c.clears()[2], 0);  // and it goes on into the box itself
  EXPECT_EQ(c.grown_clears()[3], 1);
  EXPECT_EQ(std::vector<std::int32_t>(c.unsettled().begin(), c.unsettled().end()),
            (std::vector<std::int32_t>{1, 2, 3}));
}

TEST(TwoBoxClearance, EachSideOfTheGrownBoxGrowsByItsOwn) {
  // x grown by 0.1 m above (face at 0.4 m) and not at all below (face at -0.3 m): a fragment at
  // rest 0.35 m out on the +x side is inside the grown box, its mirror image on -x clear of it.
  TwoBoxClearance c;
  TwoBoxClearance::Boxes b = still_boxes();
  b.grown = true;
  b.grow_hi_m = {0.1, 0.0, 0.0};
  b.window_s = 0.2;
  c.run(std::vector<FragmentState>{state_at({0.35, 0.0, 0.0}, Eigen::Vector3d::Zero(), 0.0),
                                   state_at({-0.35, 0.0, 0.0}, Eigen::Vector3d::Zero(), 0.0)},
        b);
  EXPECT_EQ(c.grown_clears()[0], 0);
  EXPECT_EQ(c.grown_clears()[1], 1);
}

// Growth 2 t^2 on every side over a 1 s window: 2 m at its end, 0.125, 0.5, 1.125 and 2 m at the
// ends of its four pieces. A fragment at y = 0.6 m (0.35 m above the top face) is inside the y
// slab only once the growth passes 0.35 m, after 0.418 s. Crossing x at 10 m/s from x = -1 m it
// is past x = 3 m by then, beyond the x face (at most 2.3 m): never inside the growing box. The
// whole window's box (2 m on every side) holds its path; piece by piece it is clear of each:
// 0.6 > 0.375 in the first, x from 1.5 to 4 m against 0.8 in the second, and so on. At 2 m/s it
// is at x = 0 at 0.5 s, inside the box grown by 0.5 m: never cleared.
TEST(TwoBoxClearance, PiecesOfTheWindowClearAPathThatPassesEarly) {
  TwoBoxClearance::Boxes b = still_boxes();
  b.grown = true;
  b.window_s = 1.0;
  b.cap_s = 1.0;
  const auto growth = [](double t) { return Eigen::Vector3d::Constant(2.0 * t * t); };
  b.grow_lo_m = growth(b.window_s);
  b.grow_hi_m = growth(b.window_s);
  const std::vector<FragmentState> f{state_at({-1.0, 0.6, 0.0}, {10.0, 0.0, 0.0}, 0.0),
                                     state_at({-1.0, 0.6, 0.0}, {2.0, 0.0, 0.0}, 0.0)};
  TwoBoxClearance whole;
  whole.run(f, b);
  EXPECT_EQ(whole.grown_clears()[0], 0);
  EXPECT_EQ(whole.grown_clears()[1], 0);
  b.pieces = 4;
  for (int j = 0; j < b.pieces; ++j) {
    b.piece_grow_lo_m[static_cast<std::size_t>(j)] = growth(b.window_s * (j + 1) / b.pieces);
    b.piece_grow_hi_m[static_cast<std::size_t>(j)] = growth(b.window_s * (j + 1) / b.pieces);
  }
  for (const bool wide : {true, false}) {
    TwoBoxClearance pieces;
    pieces.use_wide_lanes(wide);
    pieces.run(f, b);
    EXPECT_EQ(pieces.grown_clears()[0], 1) << wide;
    EXPECT_EQ(pieces.grown_clears()[1], 0) << wide;
    EXPECT_EQ(pieces.clears()[0], 1) << wide;  // the protected box is not grown at all
  }
  // A window of 0 s is its one instant: a fragment at rest 0.1 m beyond the top face is inside a
  // box grown by 0.2 m then, whatever the pieces.
  b.window_s = 0.0;
  b.grow_lo_m = b.grow_hi_m = Eigen::Vector3d::Constant(0.2);
  for (int j = 0; j < b.pieces; ++j) {
    b.piece_grow_lo_m[static_cast<std::size_t>(j)] = Eigen::Vector3d::Constant(0.2);
    b.piece_grow_hi_m[static_cast<std::size_t>(j)] = Eigen::Vector3d::Constant(0.2);
  }
  const std::vector<FragmentState> at_rest{
      state_at({0.0, 0.35, 0.0}, Eigen::Vector3d::Zero(), 0.0)};
  for (const bool wide : {true, false}) {
    TwoBoxClearance pieces;
    pieces.use_wide_lanes(wide);
    pieces.run(at_rest, b);
    EXPECT_EQ(pieces.grown_clears()[0], 0) << wide;
  }
}

TEST(TwoBoxClearance, APathIsExaminedUntilItReachesTheGround) {
  // The box 0.5 m below a ground at y = 0 (its top face 0.25 m below it), gravity down. Resting
  // on the ground right above it: edge-min examines one step (it falls 1.4 mm): clear. 1 cm up:
  // 0.045 s to the ground, 1 cm of fall: clear. Without the ground it falls into the box.
  TwoBoxClearance c;
  TwoBoxClearance::Boxes b = still_boxes();
  b.frame.origin_m = {0.0, -0.5, 0.0};
  b.a_mps2 = 0.5 * kG;
  b.half_gy_mps2 = 0.5 * kG.y();
  b.ground_m = 0.0;
  const std::vector<FragmentState> f{state_at({0.0, 0.0, 0.0}, Eigen::Vector3d::Zero(), 0.0),
                                     state_at({0.0, 0.01, 0.0}, Eigen::Vector3d::Zero(), 0.0)};
  c.run(f, b);
  EXPECT_EQ(c.clears()[0], 1);
  EXPECT_EQ(c.clears()[1], 1);
  b.ground_m = -INFINITY;
  c.run(f, b);
  EXPECT_EQ(c.clears()[0], 0);
  EXPECT_EQ(c.clears()[1], 0);
}

// Random fragments near the box in a moving, rotated camera-like frame, with gravity, a ground,
// a grown box seen from a still frame (reachable's) or the moving one.
struct TwoBoxCase {
  std::vector<FragmentState> fragments;
  std::vector<Parabola> local;        // in the frame, relative to its velocity
  std::vector<Parabola> local_grown;  // relative to the grown frame's velocity
  TwoBoxClearance::Boxes boxes;
  Eigen::Vector3d right, up, forward;
};
TwoBoxCase random_two_box_case(std::mt19937_64& rng, std::size_t n, bool still_grown) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  TwoBoxCase k;
  k.forward = random_unit(rng);
  k.right = k.forward.cross(Eigen::Vector3d::UnitY()).normalized();
  k.up = k.right.cross(k.forward);
  TwoBoxClearance::Boxes& b = k.boxes;
  b.frame = BoxFrame{{1.0, 1.6, -2.0}, {k.right, k.up, k.forward}, {0.0, 0.0, -2.0}};
  b.a_mps2 = Eigen::Vector3d(0.5 * kG.dot(k.right), 0.5 * kG.dot(k.up), 0.5 * kG.dot(k.forward));
  Eigen::Vector3d lo;
  Eigen::Vector3d hi;
  double t_end = 0.0;
  random_box_path(rng, lo, hi, t_end);
  b.lo_m = lo;
  b.hi_m = hi;
  b.cap_s = t_end;
  b.floor_s = kStep;
  b.ground_m = 1.6 - 3.0 * u(rng);
  b.half_gy_mps2 = 0.5 * kG.y();
  b.grown = true;
  b.grown_velocity_mps = still_grown ? Eigen::Vector3d::Zero() : b.frame.velocity_mps;
  // Each side its own growth (edge-min's sides stop growing at different times).
  for (int c = 0; c < 3; ++c) {
    b.grow_lo_m[c] = 0.5 * u(rng);
    b.grow_hi_m[c] = 0.5 * u(rng);
  }
  b.window_s = t_end * u(rng);
  const auto to_frame = [&](const Eigen::Vector3d& w) {
    return Eigen::Vector3d(w.dot(k.right), w.dot(k.up), w.dot(k.forward));
  };
  for (std::size_t i = 0; i < n; ++i) {
    Eigen::Vector3d lo_i;
    Eigen::Vector3d hi_i;
    double t_i = 0.0;
    Parabola p = random_box_path(rng, lo_i, hi_i, t_i);
    p.accel_mps2 = 2.0 * b.a_mps2;
    const Eigen::Vector3d world_p =
        b.frame.origin_m + p.p0_m.x() * k.right + p.p0_m.y() * k.up + p.p0_m.z() * k.forward;
    const Eigen::Vector3d world_v = b.frame.velocity_mps + p.v0_mps.x() * k.right +
                                    p.v0_mps.y() * k.up + p.v0_mps.z() * k.forward;
    const double r = u(rng) < 0.3 ? 0.0 : 0.2 * u(rng);
    k.fragments.push_back(state_at(world_p, world_v, r));
    k.local.push_back(Parabola{to_frame(world_p - b.frame.origin_m),
                               to_frame(world_v - b.frame.velocity_mps), 2.0 * b.a_mps2});
    k.local_grown.push_back(Parabola{to_frame(world_p - b.frame.origin_m),
                                     to_frame(world_v - b.grown_velocity_mps), 2.0 * b.a_mps2});
  }
  return k;
}

TEST(TwoBoxClearance, NeverClearsAPathThatEntersEitherBoxWithinItsOwnLookAhead) {
  std::mt19937_64 rng(22);
  int cleared = 0;
  int grown_cleared = 0;
  for (int round = 0; round < 40; ++round) {
    const TwoBoxCase k = random_two_box_case(rng, 2000, round % 2 == 0);
    TwoBoxClearance c;
    c.run(k.fragments, k.boxes);
    const TwoBoxClearance::Boxes& b = k.boxes;
    for (std::size_t i = 0; i < k.fragments.size(); ++i) {
      const FragmentState& f = k.fragments[i];
      const Eigen::Vector3d r = Eigen::Vector3d::Constant(f.radius_m);
      const double own = own_interval(f.position_m.y(), f.velocity_mps.y(), b.half_gy_mps2,
                                      b.ground_m + f.radius_m, b.cap_s, b.floor_s);
      if (c.clears()[i]) {
        ++cleared;
        ASSERT_FALSE(enters_box(k.local[i], b.lo_m - r, b.hi_m + r, own)) << round << " " << i;
      }
      if (c.grown_clears()[i]) {
        ++grown_cleared;
        ASSERT_FALSE(enters_box(k.local_grown[i], b.lo_m - b.grow_lo_m - r,
                                b.hi_m + b.grow_hi_m + r, std::min(b.window_s, own)))
            << round << " " << i;
      }
    }
  }
  EXPECT_GT(cleared, 0);
  EXPECT_GT(grown_cleared, 0);
}

// The grown box of random cases grown by base + q t^2 on each side (edge-min's bounded_accel
// growth: the turn's cap, then half the acceleration), the window in four pieces each grown by
// its end's growth: no path the pieces clear is inside the box grown by its growth at that time,
// at any of 1,000 times over its window (a sampled check: it can miss a brief entry, never report
// a false one), every path the whole window clears is still cleared, and more are.
TEST(TwoBoxClearance, PiecesNeverClearAPathThatEntersTheGrowingBox) {
  std::mt19937_64 rng(24);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  long whole_cleared = 0;
  long pieces_cleared = 0;
  for (int round = 0; round < 20; ++round) {
    TwoBoxCase k = random_two_box_case(rng, 500, round % 2 == 0);
    TwoBoxClearance::Boxes& b = k.boxes;
    Eigen::Vector3d base_lo;
    Eigen::Vector3d base_hi;
    Eigen::Vector3d q_lo;
    Eigen::Vector3d q_hi;
    for (int c = 0; c < 3; ++c) {
      base_lo[c] = 0.2 * u(rng);
      base_hi[c] = 0.2 * u(rng);
      q_lo[c] = 2.0 * u(rng);
      q_hi[c] = 2.0 * u(rng);
    }
    const auto grow_lo = [&](double t) -> Eigen::Vector3d { return base_lo + q_lo * t * t; };
    const auto grow_hi = [&](double t) -> Eigen::Vector3d { return base_hi + q_hi * t * t; };
    b.grow_lo_m = grow_lo(b.window_s);
    b.grow_hi_m = grow_hi(b.window_s);
    TwoBoxClearance whole;
    whole.run(k.fragments, b);
    b.pieces = TwoBoxClearance::Boxes::kMaxPieces;
    for (int j = 0; j < b.pieces; ++j) {
      const double end_s = b.window_s * (j + 1) / b.pieces;
      b.piece_grow_lo_m[static_cast<std::size_t>(j)] = grow_lo(end_s);
      b.piece_grow_hi_m[static_cast<std::size_t>(j)] = grow_hi(end_s);
    }
    TwoBoxClearance pieces;
    pieces.run(k.fragments, b);
    for (std::size_t i = 0; i < k.fragments.size(); ++i) {
      whole_cleared += whole.grown_clears()[i];
      pieces_cleared += pieces.grown_clears()[i];
      if (whole.grown_clears()[i]) {
        ASSERT_EQ(pieces.grown_clears()[i], 1) << round << " " << i;
      }
      ASSERT_EQ(pieces.clears()[i], whole.clears()[i]) << round << " " << i;
      if (!pieces.grown_clears()[i]) continue;
      const FragmentState& f = k.fragments[i];
      const double own = own_interval(f.position_m.y(), f.velocity_mps.y(), b.half_gy_mps2,
                                      b.ground_m + f.radius_m, b.cap_s, b.floor_s);
      const double t_end = std::min(b.window_s, own);
      const Eigen::Vector3d r = Eigen::Vector3d::Constant(f.radius_m);
      for (int s = 0; s <= 1000; ++s) {
        const double t = t_end * s / 1000.0;
        const Eigen::Vector3d x = k.local_grown[i].at(t);
        const Eigen::Vector3d lo = b.lo_m - grow_lo(t) - r;
        const Eigen::Vector3d hi = b.hi_m + grow_hi(t) + r;
        const bool inside = (x.array() >= lo.array()).all() && (x.array() <= hi.array()).all();
        ASSERT_FALSE(inside) << round << " " << i << " t " << t;
      }
    }
  }
  EXPECT_GT(whole_cleared, 0);
  EXPECT_GT(pieces_cleared, whole_cleared);
}

TEST(TwoBoxClearance, WideAndNarrowLanesAnswerTheSame) {
  std::mt19937_64 rng(23);
  for (const std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{2}, std::size_t{3},
                              std::size_t{5}, std::size_t{4097}}) {
    for (const bool still_grown : {false, true}) {
      TwoBoxCase k = random_two_box_case(rng, n, still_grown);
      // Half the cases with the window in pieces, each grown by a share of the whole's growth.
      if (n % 2 == 1) {
        k.boxes.pieces = TwoBoxClearance::Boxes::kMaxPieces;
        for (int j = 0; j < k.boxes.pieces; ++j) {
          const double share = (j + 1.0) / k.boxes.pieces;
          k.boxes.piece_grow_lo_m[static_cast<std::size_t>(j)] = share * k.boxes.grow_lo_m;
          k.boxes.piece_grow_hi_m[static_cast<std::size_t>(j)] = share * k.boxes.grow_hi_m;
        }
      }
      TwoBoxClearance wide;
      TwoBoxClearance narrow;
      narrow.use_wide_lanes(false);
      wide.run(k.fragments, k.boxes);
      narrow.run(k.fragments, k.boxes);
      ASSERT_EQ(wide.first_tier_doubts(), narrow.first_tier_doubts()) << n;
      ASSERT_TRUE(std::equal(wide.clears().begin(), wide.clears().end(), narrow.clears().begin()));
      ASSERT_TRUE(std::equal(wide.grown_clears().begin(), wide.grown_clears().end(),
                             narrow.grown_clears().begin()));
      ASSERT_TRUE(std::equal(wide.unsettled().begin(), wide.unsettled().end(),
                             narrow.unsettled().begin(), narrow.unsettled().end()));
      ASSERT_EQ(wide.max_radius_m(), narrow.max_radius_m());
    }
  }
}

// The window in pieces, each grown by a share of the whole's growth.
void set_pieces(TwoBoxClearance::Boxes& b) {
  b.pieces = TwoBoxClearance::Boxes::kMaxPieces;
  for (int j = 0; j < b.pieces; ++j) {
    const double share = (j + 1.0) / b.pieces;
    b.piece_grow_lo_m[static_cast<std::size_t>(j)] = share * b.grow_lo_m;
    b.piece_grow_hi_m[static_cast<std::size_t>(j)] = share * b.grow_hi_m;
  }
}

// The wide lanes pack the lanes the grown box's pieces are left to test, from many groups of
// four, into full groups. Fragments the pieces decide (those the whole window leaves in doubt)
// mixed with fragments settled before, in groups of four of every pattern and at every offset
// of the packed lanes, must each be answered as when alone, and the unsettled listed in order
// as by the narrow lanes.
TEST(TwoBoxClearance, PackedPiecesAnswerAsEachFragmentAlone) {
  std::mt19937_64 rng(25);
  int cleared_by_pieces = 0;
  int left_by_pieces = 0;
  for (int round = 0; round < 6; ++round) {
    TwoBoxCase k = random_two_box_case(rng, 1000, round % 2 == 0);
    TwoBoxClearance whole;
    whole.run(k.fragments, k.boxes);
    std::vector<FragmentState> decided;  // by the pieces
    std::vector<FragmentState> settled;  // before them
    for (std::size_t i = 0; i < k.fragments.size(); ++i) {
      (whole.grown_clears()[i] ? settled : decided).push_back(k.fragments[i]);
    }
    ASSERT_GE(decided.size(), 40u) << round;
    ASSERT_GE(settled.size(), 40u) << round;
    set_pieces(k.boxes);
    // Patterns 1..15 over and over (a bit for each lane drawn from `decided`), a pattern of 0
    // every fifth group, and a tail of three that goes to the narrow lanes.
    std::vector<FragmentState> mixed;
    std::size_t next_decided = 0;
    std::size_t next_settled = 0;
    for (int group = 0; next_decided + 4 <= decided.size() && next_settled + 4 <= settled.size();
         ++group) {
      const int pattern = group % 5 == 4 ? 0 : 1 + group % 15;
      for (int lane = 0; lane < 4; ++lane) {
        mixed.push_back(((pattern >> lane) & 1) != 0 ? decided[next_decided++]
                                                     : settled[next_settled++]);
      }
    }
    for (int tail = 0; tail < 3; ++tail) mixed.push_back(decided[tail]);
    TwoBoxClearance wide;
    TwoBoxClearance narrow;
    narrow.use_wide_lanes(false);
    wide.run(mixed, k.boxes);
    narrow.run(mixed, k.boxes);
    ASSERT_TRUE(std::equal(wide.unsettled().begin(), wide.unsettled().end(),
                           narrow.unsettled().begin(), narrow.unsettled().end()))
        << round;
    TwoBoxClearance alone;
    for (std::size_t i = 0; i < mixed.size(); ++i) {
      alone.run(std::span<const FragmentState>(&mixed[i], 1), k.boxes);
      ASSERT_EQ(wide.clears()[i], alone.clears()[0]) << round << " " << i;
      ASSERT_EQ(wide.grown_clears()[i], alone.grown_clears()[0]) << round << " " << i;
      ASSERT_EQ(narrow.grown_clears()[i], alone.grown_clears()[0]) << round << " " << i;
    }
    for (const FragmentState& f : decided) {
      alone.run(std::span<const FragmentState>(&f, 1), k.boxes);
      ++(alone.grown_clears()[0] ? cleared_by_pieces : left_by_pieces);
    }
  }
  // Both answers occur, so a lane answered with another's would show.
  EXPECT_GT(cleared_by_pieces, 100);
  EXPECT_GT(left_by_pieces, 100);
}

// The wide lanes' first loop keeps what the second needs only when the last run left more than a
// few groups in doubt; otherwise the second gathers and tests its groups again. Runs in turn in
// doubt and nearly all settled (the same fragments 100 km off, but three), each after either, on
// one clearance: every run answers as the narrow lanes do.
TEST(TwoBoxClearance, WideLanesAnswerAlikeAfterAnyRun) {
  std::mt19937_64 rng(26);
  for (int round = 0; round < 6; ++round) {
    TwoBoxCase k = random_two_box_case(rng, 1001, round % 2 == 0);
    // From the third round on, the grown box far larger, so that the first tier clears many a
    // fragment of the box but not of the grown box, and the second tier must not take one
    // answer for the other.
    if (round >= 2) {
      k.boxes.grow_lo_m *= 10.0;
      k.boxes.grow_hi_m *= 10.0;
    }
    set_pieces(k.boxes);
    std::vector<FragmentState> far_off = k.fragments;
    for (FragmentState& f : far_off) f.position_m.x() += 1e5;
    // Three left in doubt among the settled, in three groups of four: fewer than the first loop
    // keeps for (a 64th of the groups).
    TwoBoxClearance first;
    first.run(k.fragments, k.boxes);
    ASSERT_GE(first.unsettled().size(), 3u);
    for (std::size_t j = 0; j < 3; ++j) {
      const std::size_t from = static_cast<std::size_t>(first.unsettled()[j]);
      far_off[400 * j] = k.fragments[from];
    }
    TwoBoxClearance wide;
    int in_doubt_runs = 0;
    for (const bool doubtful : {false, true, true, false, false, true, false}) {
      const std::vector<FragmentState>& f = doubtful ? k.fragments : far_off;
      TwoBoxClearance narrow;
      narrow.use_wide_lanes(false);
      wide.run(f, k.boxes);
      narrow.run(f, k.boxes);
      ASSERT_EQ(wide.first_tier_doubts(), narrow.first_tier_doubts()) << round;
      ASSERT_TRUE(std::equal(wide.clears().begin(), wide.clears().end(), narrow.clears().begin()))
          << round << " " << doubtful;
      ASSERT_TRUE(std::equal(wide.grown_clears().begin(), wide.grown_clears().end(),
                             narrow.grown_clears().begin()))
          << round << " " << doubtful;
      ASSERT_TRUE(std::equal(wide.unsettled().begin(), wide.unsettled().end(),
                             narrow.unsettled().begin(), narrow.unsettled().end()))
          << round << " " << doubtful;
      in_doubt_runs += wide.first_tier_doubts() > 100 ? 1 : 0;
      if (!doubtful) {
        EXPECT_EQ(wide.first_tier_doubts(), 3u) << round;
      }
    }
    EXPECT_EQ(in_doubt_runs, 3) << round;
  }
}

}  // namespace
}  // namespace fragsim
