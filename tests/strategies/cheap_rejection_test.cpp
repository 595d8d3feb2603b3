// The cheap rejection (cheap_rejection.hpp) must be conservative: whatever it calls clear, the
// exact solve calls clear too. Hand-checkable cases with worked-out distances, then randomised
// families (fixed seeds) built to sit on the edge: grazing paths, paths starting on the surface,
// paths reaching it at the horizon. And the batched tests must answer exactly as the single ones.

#include "strategies/cheap_rejection.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <span>
#include <vector>

#include "geometry/first_root.hpp"
#include "strategies/collision_prediction.hpp"
#include "strategies/edge_min_strategy.hpp"

namespace fragsim {
namespace {

const Eigen::Vector3d kG(0.0, -9.81, 0.0);

// The path relative to the region's centre.
Parabola line(const Eigen::Vector3d& d, const Eigen::Vector3d& v,
              const Eigen::Vector3d& g = Eigen::Vector3d::Zero()) {
  return {d, v, g};
}

// The exact answer the strategies act on: first_nonpositive on the ball's quartic.
bool enters_ball(const Parabola& p, double r0, double growth, double t_end) {
  return first_nonpositive(ball_contact_quartic(p, Eigen::Vector3d::Zero(), r0, growth), 0.0, t_end)
      .has_value();
}

// ---- The ball: cases worked out by hand ----

TEST(BallRejection, FiredStraightAtTheCentreIsNeverCleared) {
  // 10 m out, at the centre at tau = 1 s (aimed up by g / 2 against gravity), fixed and growing
  // ball.
  for (const Eigen::Vector3d& g : {Eigen::Vector3d(Eigen::Vector3d::Zero()), kG}) {
    const Parabola p = line({0.0, 0.0, -10.0}, Eigen::Vector3d(0.0, 0.0, 10.0) - 0.5 * g, g);
    EXPECT_FALSE(path_clears_ball(p, 0.3, 0.0, 3.0));
    EXPECT_FALSE(path_clears_ball(p, 0.3, 3.0, 3.0));
    EXPECT_TRUE(enters_ball(p, 0.3, 0.0, 3.0));
  }
}

TEST(BallRejection, MissByAKnownDistance) {
  // Along x, 2 m from the centre at its closest (tau = 5 s). A 1.99 m ball is missed by 1 cm,
  // a hundred times the margin: cleared. A 2.01 m ball is entered: not cleared.
  const Parabola p = line({-5.0, 2.0, 0.0}, {1.0, 0.0, 0.0});
  EXPECT_TRUE(path_clears_ball(p, 1.99, 0.0, 10.0));
  EXPECT_FALSE(enters_ball(p, 1.99, 0.0, 10.0));
  EXPECT_FALSE(path_clears_ball(p, 2.01, 0.0, 10.0));
  EXPECT_TRUE(enters_ball(p, 2.01, 0.0, 10.0));
  // Only the interval counts: by tau = 4 s it is still sqrt(1 + 4) = 2.236 m away.
  EXPECT_TRUE(path_clears_ball(p, 2.2, 0.0, 4.0));
  EXPECT_FALSE(enters_ball(p, 2.2, 0.0, 4.0));
  // Closest in the middle of one of the eighths of [0, 10] (tau = 5.625 s), where the Bernstein
  // bound is loosest: on that 1.25 s piece Q = (tau - 5.625)^2 + 4 - R^2 has coefficients down to
  // 4 - R^2 - 1.25^2 / 12, positive for a 5 cm miss (R = 1.95: 0.1975 - 0.130).
  const Parabola mid = line({-5.625, 2.0, 0.0}, {1.0, 0.0, 0.0});
  EXPECT_TRUE(path_clears_ball(mid, 1.95, 0.0, 10.0));
  EXPECT_FALSE(enters_ball(mid, 1.95, 0.0, 10.0));
}

TEST(BallRejection, TangentPathIsNotCleared) {
  // Exactly 1 m from the centre at tau = 5 s: the solve calls it a touch.
  const Parabola p = line({-5.0, 1.0, 0.0}, {1.0, 0.0, 0.0});
  EXPECT_FALSE(path_clears_ball(p, 1.0, 0.0, 10.0));
  EXPECT_TRUE(enters_ball(p, 1.0, 0.0, 10.0));
}

TEST(BallRejection, StartingInsideOrOnTheSurfaceIsNotCleared) {
  EXPECT_FALSE(path_clears_ball(line({0.5, 0.0, 0.0}, {3.0, 0.0, 0.0}), 1.0, 0.0, 10.0));
  EXPECT_FALSE(path_clears_ball(line({1.0, 0.0, 0.0}, {3.0, 0.0, 0.0}), 1.0, 0.0, 10.0));
}

TEST(BallRejection, RecedingAndFallingAwayAreCleared) {
  EXPECT_TRUE(path_clears_ball(line({0.0, 0.0, -5.0}, {0.0, 1.0, -8.0}, kG), 1.0, 0.0, 3.0));
  // Dropped 1 m beside and 3 m below a 1 m ball: falls away.
  EXPECT_TRUE(path_clears_ball(line({1.0, -3.0, 0.0}, Eigen::Vector3d::Zero(), kG), 1.0, 0.0, 3.0));
  // A ball growing at 1 m/s from 1 m never catches a fragment leaving at 2 m/s from 2 m.
  EXPECT_TRUE(path_clears_ball(line({0.0, 0.0, 2.0}, {0.0, 0.0, 2.0}), 1.0, 1.0, 3.0));
  // ...but one growing at 3 m/s does, at tau = 1 s.
  EXPECT_FALSE(path_clears_ball(line({0.0, 0.0, 2.0}, {0.0, 0.0, 2.0}), 1.0, 3.0, 3.0));
}

TEST(BallRejection, FallingOntoTheBallAfterTheHorizonIsCleared) {
  // Dropped from 10 m onto a 1 m ball: it arrives at tau = sqrt(1.8) = 1.342 s (g = 10).
  const Parabola p = line({0.0, 10.0, 0.0}, Eigen::Vector3d::Zero(), {0.0, -10.0, 0.0});
  EXPECT_TRUE(path_clears_ball(p, 1.0, 0.0, 1.3));
  EXPECT_FALSE(path_clears_ball(p, 1.0, 0.0, 1.4));
}

TEST(BallRejection, InDoubtOnBadInput) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const Parabola far = line({0.0, 0.0, -100.0}, {0.0, 0.0, -1.0});
  EXPECT_TRUE(path_clears_ball(far, 1.0, 0.0, 3.0));
  EXPECT_FALSE(path_clears_ball(far, 1.0, 0.0, -1.0));
  EXPECT_FALSE(path_clears_ball(far, 1.0, 0.0, nan));
  EXPECT_FALSE(path_clears_ball(far, 1.0, 0.0, inf));
  EXPECT_FALSE(path_clears_ball(far, nan, 0.0, 3.0));
  EXPECT_FALSE(path_clears_ball(line({nan, 0.0, -100.0}, {0.0, 0.0, -1.0}), 1.0, 0.0, 3.0));
  EXPECT_FALSE(path_clears_ball(line({0.0, 0.0, -100.0}, {inf, 0.0, -1.0}), 1.0, 0.0, 3.0));
}

// ---- The ball: randomised families on the edge ----

Eigen::Vector3d random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  return Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
}

struct BallCase {
  Parabola path;
  double r0 = 0.0;
  double growth = 0.0;
  double t_end = 0.0;
};

// Random paths and balls over many scales (as tests/geometry/first_root_reference_test.cpp), then
// moved so that the path grazes the ball, starts on it or reaches it at the horizon, within
// +-1e-13..1e-1 m (family 0 leaves them random).
BallCase random_ball_case(std::mt19937_64& rng, int family) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto log_uniform = [&](double lo_exp, double hi_exp) {
    return std::pow(10.0, lo_exp + (hi_exp - lo_exp) * u(rng));
  };
  BallCase k;
  Eigen::Vector3d g = Eigen::Vector3d::Zero();
  const double gravity = u(rng);
  if (gravity < 0.5) {
    g = kG;
  } else if (gravity < 0.8) {
    g = 20.0 * u(rng) * random_unit(rng);
  }
  const Eigen::Vector3d v = u(rng) < 0.05
                                ? Eigen::Vector3d(Eigen::Vector3d::Zero())
                                : Eigen::Vector3d(log_uniform(-1, 1.6) * random_unit(rng));
  const BallisticPath path{log_uniform(-2, 2) * random_unit(rng), v, g};
  k.r0 = log_uniform(-1.7, 1);
  k.growth = u(rng) < 0.5 ? 0.0 : 10.0 * u(rng);
  k.t_end = log_uniform(-2, 1);
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  const double delta = (u(rng) < 0.5 ? -1.0 : 1.0) * log_uniform(-13, -1);
  if (family == 1) {
    // At t*, the distance is stationary relative to the growing radius and R(t*) + delta.
    const double ts = k.t_end * u(rng);
    const Eigen::Vector3d vel = path.v0_mps + path.accel_mps2 * ts;
    if (vel.norm() > k.growth) {
      const Eigen::Vector3d along = vel.normalized();
      Eigen::Vector3d side = random_unit(rng);
      side = (side - side.dot(along) * along).normalized();
      const double a = k.growth / vel.norm();
      const Eigen::Vector3d dir = a * along + std::sqrt(1.0 - a * a) * side;
      centre = path.at(ts) - (k.r0 + k.growth * ts + delta) * dir;
    }
  } else if (family == 2) {
    centre = path.p0_m - (k.r0 + delta) * random_unit(rng);
  } else if (family == 3) {
    centre = path.at(k.t_end) - (k.r0 + k.growth * k.t_end + delta) * random_unit(rng);
  }
  k.path = {path.p0_m - centre, path.v0_mps, path.accel_mps2};
  return k;
}

TEST(BallRejection, NeverClearsWhatTheSolveCallsACandidate) {
  std::mt19937_64 rng(11);
  int cleared = 0;
  int misses = 0;
  for (int family = 0; family < 4; ++family) {
    for (int n = 0; n < 20000; ++n) {
      const BallCase k = random_ball_case(rng, family);
      const bool enters = enters_ball(k.path, k.r0, k.growth, k.t_end);
      const bool clear = path_clears_ball(k.path, k.r0, k.growth, k.t_end);
      ASSERT_FALSE(clear && enters) << "family " << family << " case " << n;
      misses += enters ? 0 : 1;
      cleared += clear ? 1 : 0;
    }
  }
  // And it is worth having: it settles most of the misses (near-misses within 1e-13 m included).
  EXPECT_GT(cleared, misses * 6 / 10) << cleared << " of " << misses;
}

TEST(BallRejection, BatchAnswersAsOnePathAtATime) {
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const double growth : {0.0, 3.0}) {
    for (const std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{2}, std::size_t{7},
                                std::size_t{2000}, std::size_t{2001}}) {
      BallClearance batch;
      batch.resize(n);
      std::vector<BallCase> cases(n);
      const Eigen::Vector3d a = u(rng) < 0.5 ? Eigen::Vector3d(0.5 * kG) : Eigen::Vector3d::Zero();
      for (std::size_t i = 0; i < n; ++i) {
        cases[i] = random_ball_case(rng, static_cast<int>(i % 4));
        cases[i].path.accel_mps2 = 2.0 * a;
        batch.set(i, cases[i].path.p0_m, cases[i].path.v0_mps, cases[i].r0, cases[i].t_end);
      }
      const auto clears = batch.run(a, growth);
      ASSERT_EQ(clears.size(), n);
      for (std::size_t i = 0; i < n; ++i) {
        ASSERT_EQ(clears[i] != 0,
                  path_clears_ball(cases[i].path, cases[i].r0, growth, cases[i].t_end))
            << "path " << i << " of " << n;
      }
    }
  }
}

// ---- The box ----

// Every time in [0, t_end] where lo <= x(t) <= hi holds for all three coordinates, found from
// the roots of each coordinate against each face (between consecutive break times nothing
// changes), checked at the break times (with a tolerance far below the rejection's margin, so a
// touch counts) and between them.
bool enters_box(const Parabola& p, const Eigen::Vector3d& lo, const Eigen::Vector3d& hi,
                double t_end) {
  std::vector<double> times{0.0, t_end};
  for (int i = 0; i < 3; ++i) {
    for (double face : {lo[i], hi[i]}) {
      for (double r : real_roots({p.p0_m[i] - face, p.v0_mps[i], p.half_accel_mps2()[i], 0.0, 0.0},
                                 0.0, t_end)) {
        times.push_back(r);
      }
    }
  }
  std::sort(times.begin(), times.end());
  const double scale = p.p0_m.lpNorm<1>() + p.v0_mps.lpNorm<1>() * t_end +
                       p.half_accel_mps2().lpNorm<1>() * t_end * t_end + lo.lpNorm<1>() +
                       hi.lpNorm<1>();
  const auto inside = [&](double t, double tol) {
    for (int i = 0; i < 3; ++i) {
      const double x = p.p0_m[i] + t * (p.v0_mps[i] + t * p.half_accel_mps2()[i]);
      if (x < lo[i] - tol || x > hi[i] + tol) return false;
    }
    return true;
  };
  for (std::size_t k = 0; k < times.size(); ++k) {
    if (inside(times[k], 1e-12 * scale)) return true;
    if (k + 1 < times.size() && inside(0.5 * (times[k] + times[k + 1]), 0.0)) return true;
  }
  return false;
}

const Eigen::Vector3d kLo(-0.3, -0.25, -0.2);
const Eigen::Vector3d kHi(0.3, 0.25, 0.25);

TEST(BoxRejection, FiredStraightAtTheBoxIsNeverCleared) {
  for (const Eigen::Vector3d& g : {Eigen::Vector3d(Eigen::Vector3d::Zero()), kG}) {
    // Aimed so that gravity is compensated: at the centre at tau = 1 s.
    const Parabola p = line({0.0, 0.0, 10.0}, Eigen::Vector3d(0.0, 0.0, -10.0) - 0.5 * g, g);
    EXPECT_FALSE(path_clears_box(p, kLo, kHi, 3.0));
    EXPECT_TRUE(enters_box(p, kLo, kHi, 3.0));
  }
}

TEST(BoxRejection, PassingBesideByAKnownDistance) {
  // Along z at x = 0.31, 1 cm beyond the x face: cleared; at x = 0.29: enters.
  EXPECT_TRUE(path_clears_box(line({0.31, 0.0, 10.0}, {0.0, 0.0, -10.0}), kLo, kHi, 3.0));
  EXPECT_FALSE(path_clears_box(line({0.29, 0.0, 10.0}, {0.0, 0.0, -10.0}), kLo, kHi, 3.0));
  // Moving sideways: at x = 0.29 + 0.5 tau it is inside the x slab only while z is still above the
  // box (z = 10 - 10 tau > 0.25 for tau < 0.975): the z window rules it out.
  const Parabola late = line({0.29, 0.0, 10.0}, {0.5, 0.0, -10.0});
  EXPECT_FALSE(enters_box(late, kLo, kHi, 3.0));
  EXPECT_TRUE(path_clears_box(late, kLo, kHi, 3.0));
  // Crossing the x slab while z passes the box: enters.
  const Parabola crossing = line({-0.5, 0.0, 10.0}, {0.5, 0.0, -10.0});
  EXPECT_TRUE(enters_box(crossing, kLo, kHi, 3.0));
  EXPECT_FALSE(path_clears_box(crossing, kLo, kHi, 3.0));
}

TEST(BoxRejection, GrazingTheTopFaceIsNotCleared) {
  // Thrown so that its apex, y = 0.25 exactly, is reached at tau = 1 s, when it is at the centre
  // in x and z: it touches the top face.
  const double vy = 9.81;
  const Parabola p = line({0.0, 0.25 - 0.5 * 9.81, 10.0}, {0.0, vy, -10.0}, kG);
  EXPECT_TRUE(enters_box(p, kLo, kHi, 3.0));
  EXPECT_FALSE(path_clears_box(p, kLo, kHi, 3.0));
  // Its apex 1 cm above the box: cleared.
  const Parabola above = line({0.0, 0.26 - 0.5 * 9.81, 10.0}, {0.0, vy, -10.0}, kG);
  EXPECT_FALSE(enters_box(above, kLo, kHi, 3.0));
  EXPECT_TRUE(path_clears_box(above, kLo, kHi, 3.0));
}

TEST(BoxRejection, InDoubtOnBadInput) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Parabola far = line({10.0, 0.0, 10.0}, {0.0, 0.0, 1.0});
  EXPECT_TRUE(path_clears_box(far, kLo, kHi, 3.0));
  EXPECT_FALSE(path_clears_box(far, kLo, kHi, -1.0));
  EXPECT_FALSE(path_clears_box(far, kLo, kHi, nan));
  EXPECT_FALSE(path_clears_box(line({nan, 0.0, 10.0}, {0.0, 0.0, 1.0}), kLo, kHi, 3.0));
}

// Random paths near the box: aimed at a random point of the box grown by up to 1 m (so many pass
// close by), possibly grazing a face at a random time within +-1e-13..1e-1 m.
Parabola random_box_path(std::mt19937_64& rng, Eigen::Vector3d& lo, Eigen::Vector3d& hi,
                         double& t_end) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto log_uniform = [&](double lo_exp, double hi_exp) {
    return std::pow(10.0, lo_exp + (hi_exp - lo_exp) * u(rng));
  };
  for (int i = 0; i < 3; ++i) {
    lo[i] = -log_uniform(-2, 0);
    hi[i] = log_uniform(-2, 0);
  }
  t_end = log_uniform(-2, 1);
  Eigen::Vector3d g = Eigen::Vector3d::Zero();
  if (u(rng) < 0.7) g = 20.0 * u(rng) * random_unit(rng);
  const double t_hit = t_end * u(rng) * 1.2;
  Eigen::Vector3d target;
  for (int i = 0; i < 3; ++i) target[i] = lo[i] - 1.0 + (hi[i] - lo[i] + 2.0) * u(rng);
  const int face = static_cast<int>(u(rng) * 7.0);  // 6: no face
  const double delta = (u(rng) < 0.5 ? -1.0 : 1.0) * log_uniform(-13, -1);
  if (face < 6) {
    const int axis = face / 2;
    target[axis] = (face % 2 == 0 ? lo[axis] : hi[axis]) + delta;
  }
  const Eigen::Vector3d start = target + log_uniform(-1, 2) * random_unit(rng);
  // x(t_hit) = target; a grazing one has x'(t_hit) = 0 along the face's axis.
  Eigen::Vector3d v = (target - start) / std::max(t_hit, 1e-3) - 0.5 * g * t_hit;
  Parabola p{start, v, 0.5 * g};
  if (face < 6) {
    const int axis = face / 2;
    // Vertex of that coordinate at t_hit, passing through target there.
    p.v0_mps[axis] = -2.0 * p.half_accel_mps2()[axis] * t_hit;
    p.p0_m[axis] = target[axis] - t_hit * (p.v0_mps[axis] + t_hit * p.half_accel_mps2()[axis]);
  }
  return p;
}

TEST(BoxRejection, NeverClearsAPathThatEntersTheBox) {
  std::mt19937_64 rng(13);
  int cleared = 0;
  int misses = 0;
  for (int n = 0; n < 100000; ++n) {
    Eigen::Vector3d lo;
    Eigen::Vector3d hi;
    double t_end = 0.0;
    const Parabola p = random_box_path(rng, lo, hi, t_end);
    const bool enters = enters_box(p, lo, hi, t_end);
    const bool clear = path_clears_box(p, lo, hi, t_end);
    ASSERT_FALSE(clear && enters) << "case " << n;
    misses += enters ? 0 : 1;
    cleared += clear ? 1 : 0;
  }
  EXPECT_GT(cleared, misses * 8 / 10) << cleared << " of " << misses;
}

FragmentState fragment_at(const Eigen::Vector3d& p, const Eigen::Vector3d& v, double radius) {
  FragmentState f;
  f.position_m = p;
  f.velocity_mps = v;
  f.radius_m = radius;
  return f;
}

TEST(BoxRejection, BatchAnswersAsOnePathAtATime) {
  // Seen from the world frame itself, the batch's paths are the single test's, bit for bit.
  std::mt19937_64 rng(14);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  BoxClearance batch;  // reused, as edge-min does
  for (const std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{5}, std::size_t{3001}}) {
    Eigen::Vector3d lo;
    Eigen::Vector3d hi;
    double t_end = 0.0;
    std::vector<Parabola> paths(n);
    std::vector<FragmentState> fragments(n);
    const Eigen::Vector3d a = 0.5 * 20.0 * u(rng) * random_unit(rng);
    const Parabola first = random_box_path(rng, lo, hi, t_end);  // fixes the box and t_end
    for (std::size_t i = 0; i < n; ++i) {
      Eigen::Vector3d lo_i;
      Eigen::Vector3d hi_i;
      double t_i = 0.0;
      paths[i] = i == 0 ? first : random_box_path(rng, lo_i, hi_i, t_i);
      paths[i].accel_mps2 = 2.0 * a;
      fragments[i] = fragment_at(paths[i].p0_m, paths[i].v0_mps, u(rng) < 0.5 ? 0.0 : 0.2 * u(rng));
    }
    const auto clears = batch.run(fragments, BoxFrame{}, a, lo, hi, t_end);
    ASSERT_EQ(clears.size(), n);
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Vector3d g = Eigen::Vector3d::Constant(fragments[i].radius_m);
      ASSERT_EQ(clears[i] != 0, path_clears_box(paths[i], lo - g, hi + g, t_end)) << i;
    }
  }
}

TEST(BoxRejection, BatchInAMovingRotatedFrameIsConservative) {
  // A camera-like frame: the batch turns world paths into it; none it clears enters the box.
  std::mt19937_64 rng(15);
  const Eigen::Vector3d forward = random_unit(rng);
  const Eigen::Vector3d right = forward.cross(Eigen::Vector3d::UnitY()).normalized();
  const Eigen::Vector3d up = right.cross(forward);
  const BoxFrame frame{{1.0, 1.6, -2.0}, {right, up, forward}, {0.0, 0.0, -2.0}};
  const Eigen::Vector3d a(0.5 * kG.dot(right), 0.5 * kG.dot(up), 0.5 * kG.dot(forward));
  const std::size_t n = 20001;
  std::vector<Parabola> local(n);
  std::vector<FragmentState> fragments(n);
  Eigen::Vector3d lo;
  Eigen::Vector3d hi;
  double t_end = 0.0;
  random_box_path(rng, lo, hi, t_end);
  for (std::size_t i = 0; i < n; ++i) {
    Eigen::Vector3d lo_i;
    Eigen::Vector3d hi_i;
    double t_i = 0.0;
    local[i] = random_box_path(rng, lo_i, hi_i, t_i);
    local[i].accel_mps2 = 2.0 * a;
    const Eigen::Vector3d& d = local[i].p0_m;
    const Eigen::Vector3d& v = local[i].v0_mps;
    fragments[i] =
        fragment_at(frame.origin_m + d.x() * right + d.y() * up + d.z() * forward,
                    frame.velocity_mps + v.x() * right + v.y() * up + v.z() * forward, 0.0);
  }
  BoxClearance batch;
  const auto clears = batch.run(fragments, frame, a, lo, hi, t_end);
  int cleared = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!clears[i]) continue;
    ++cleared;
    ASSERT_FALSE(enters_box(local[i], lo, hi, t_end)) << i;
  }
  EXPECT_GT(cleared, 0);
}

// ---- edge-min's two boxes (TwoBoxClearance) ----

constexpr double kStep = 1.0 / 60.0;

// edge-min's own look-ahead for a path: until it comes down through the ground, within [floor,
// cap].
double own_interval(double y, double vy, double half_gy, double ground, double cap, double floor) {
  return std::max(std::min(EdgeMinStrategy::time_to_ground_s(y, vy, half_gy, ground), cap), floor);
}

TEST(TwoBoxRejection, IntervalBoundCoversEdgeMinsLookAhead) {
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

TEST(TwoBoxRejection, HandCasesForTheProtectedBox) {
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

TEST(TwoBoxRejection, TheFirstTierIsTheBallAroundTheFarthestCorner) {
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

TEST(TwoBoxRejection, HandCasesForTheGrownBox) {
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

TEST(TwoBoxRejection, EachSideOfTheGrownBoxGrowsByItsOwn) {
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
TEST(TwoBoxRejection, PiecesOfTheWindowClearAPathThatPassesEarly) {
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

TEST(TwoBoxRejection, APathIsExaminedUntilItReachesTheGround) {
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

TEST(TwoBoxRejection, NeverClearsAPathThatEntersEitherBoxWithinItsOwnLookAhead) {
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
TEST(TwoBoxRejection, PiecesNeverClearAPathThatEntersTheGrowingBox) {
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

TEST(TwoBoxRejection, WideAndNarrowLanesAnswerTheSame) {
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
TEST(TwoBoxRejection, PackedPiecesAnswerAsEachFragmentAlone) {
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
TEST(TwoBoxRejection, WideLanesAnswerAlikeAfterAnyRun) {
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
