// edge-min against cameras that turn as fast as they like (docs/camera_models.md, section 2):
// each side of the protected box grows with the turn's chord, never past the ball every
// orientation of the box lies in. Driven through StepContext with a hand-integrated loop
// (semi-implicit Euler, as ODE steps), no world.
//
// The camera sits at the origin looking down -z with the default frustum (near 0.1 m, 60 degrees,
// 16:9) and a 0.3 x 0.2 x 0.3 m body; margin 0.05 m. The protected box B is then 0.2 m to each
// side, 0.15 m up and down and 0.2 m in depth each way; its farthest corner is
// rot = |(0.2, 0.15, 0.2)| = 0.3202 m from the eye, so with a fragment of radius 0.05 m no
// orientation of B comes within reach of a centre farther than R = 0.3702 m from the eye. The
// camera declares that it cannot move (V_c = 0, A = 0), so only the turn grows the region.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>

#include "control/strategies/edge_min_strategy.hpp"

namespace fragsim {
namespace {

constexpr double kDt = 1.0 / 60.0;
constexpr double kRadius = 0.05;
constexpr double kAMax = 50.0;
// B's half extents (body + margin) and its farthest corner's distance.
const Eigen::Vector3d kHalf(0.2, 0.15, 0.2);
const double kRot = kHalf.norm();  // 0.3202 m
// 180 degrees a step: any orientation within two steps.
constexpr double kHalfTurnPerStep_radps = kPi / kDt;

EdgeMinParams params(CameraModel model = CameraModel::kBoundedAccel) {
  EdgeMinParams p;
  p.camera_model = model;
  p.a_max_mps2 = kAMax;
  return p;
}

FragmentState fragment(const Eigen::Vector3d& pos_m, const Eigen::Vector3d& vel_mps) {
  FragmentState f;
  f.position_m = pos_m;
  f.velocity_mps = vel_mps;
  f.half_extents_m = Eigen::Vector3d::Constant(0.02);
  f.mass_kg = 2.0;
  f.radius_m = kRadius;
  return f;
}

// The camera at the origin rolled by `roll_rad` about its view axis (-z), which cannot move and
// turns at most `turn_radps`.
StepContext context(double roll_rad, double turn_radps, std::span<const FragmentState> fragments,
                    double t_s, double end_s) {
  StepContext ctx;
  ctx.t_s = t_s;
  ctx.dt_s = kDt;
  ctx.end_time_s = end_s;
  ctx.camera.right = {std::cos(roll_rad), std::sin(roll_rad), 0.0};
  ctx.camera.up = {-std::sin(roll_rad), std::cos(roll_rad), 0.0};
  ctx.camera.forward = {0.0, 0.0, -1.0};
  ctx.camera_max_speed_mps = 0.0;
  ctx.camera_max_accel_mps2 = 0.0;
  ctx.camera_max_turn_degps = turn_radps * 180.0 / kPi;
  ctx.camera_body_half_m = {0.15, 0.1, 0.15};
  ctx.fragments = fragments;
  return ctx;
}

// The distance from a fragment's centre to B seen from a camera rolled by `roll_rad`: it touches
// the camera when this is below its radius.
double distance_to_box_m(const Eigen::Vector3d& p_m, double roll_rad) {
  const Eigen::Vector3d c(p_m.x() * std::cos(roll_rad) + p_m.y() * std::sin(roll_rad),
                          -p_m.x() * std::sin(roll_rad) + p_m.y() * std::cos(roll_rad), -p_m.z());
  return (c.cwiseAbs() - kHalf).cwiseMax(0.0).norm();
}

struct Flight {
  double closest_m = std::numeric_limits<double>::infinity();  // least distance to B
  double first_push_s = std::numeric_limits<double>::infinity();
  bool pushed = false;
  bool candidate = false;
  double max_accel_mps2 = 0.0;
};

// A fragment flown past the camera for 1.2 s while the camera keeps its view until `spin_s`, then
// rolls by `roll_rad` in one step (the declared turn rate allows up to 180 degrees a step).
Flight fly(const EdgeMinParams& p, FragmentState f, double turn_radps, double spin_s,
           double roll_rad) {
  EdgeMinStrategy strategy(p);
  strategy.reset(1);
  Flight out;
  StepOutput step;
  const int steps = 72;
  for (int k = 0; k < steps; ++k) {
    const double t = k * kDt;
    const double roll = t >= spin_s ? roll_rad : 0.0;
    const std::array<FragmentState, 1> frags{f};
    step.clear();
    strategy.step(context(roll, turn_radps, frags, t, steps * kDt), step);
    out.candidate = out.candidate || !step.activity.candidates.empty();
    Eigen::Vector3d a = Eigen::Vector3d::Zero();
    for (const AppliedForce& force : step.forces) a = force.force_N / f.mass_kg;
    if (!a.isZero() && !out.pushed) out.first_push_s = t;
    out.pushed = out.pushed || !a.isZero();
    out.max_accel_mps2 = std::max(out.max_accel_mps2, a.norm());
    f.velocity_mps += a * kDt;
    f.position_m += f.velocity_mps * kDt;
    out.closest_m = std::min(out.closest_m, distance_to_box_m(f.position_m, roll));
  }
  return out;
}

// Rolled by atan2(0.2, 0.15) = 53.13 degrees, B's corner (0.2, 0.15) points straight up: its
// reach there is |(0.2, 0.15)| = 0.25 m. A fragment passing 0.28 m above the eye (outside B grown
// by its radius, 0.2 m up) is then 0.03 m from B: a hit by 2 cm.
const double kCornerUp_rad = std::atan2(0.2, 0.15);
// Along the view axis at 4 m/s, level with the eye at t = 1 s; the camera rolls at 0.98 s.
FragmentState passing(double height_m) {
  return fragment({0.0, height_m, -4.0}, {0, 0, 4.0});
}
constexpr double kSpin_s = 0.98;

TEST(EdgeMinStrategyAnyTurn, ACameraThatRollsIntoAPassingFragmentIsHitWithoutTheTurn) {
  // The geometry above, checked: the constant model and a declared turn rate of 0 leave the
  // fragment alone until the roll (it misses B as it is), and the roll brings B within 0.03 m of
  // it; the push they start once they see it inside is too late to keep it 5 mm clear.
  const double tol_m = 1e-9;
  EXPECT_NEAR(distance_to_box_m({0.0, 0.28, 0.0}, kCornerUp_rad), 0.03, tol_m);
  const Flight constant =
      fly(params(CameraModel::kConstant), passing(0.28), 0.0, kSpin_s, kCornerUp_rad);
  EXPECT_GE(constant.first_push_s, kSpin_s);
  EXPECT_LT(constant.closest_m, kRadius - 5e-3);
  const Flight no_turn = fly(params(), passing(0.28), 0.0, kSpin_s, kCornerUp_rad);
  EXPECT_GE(no_turn.first_push_s, kSpin_s);
  EXPECT_LT(no_turn.closest_m, kRadius - 5e-3);
}

TEST(EdgeMinStrategyAnyTurn, AFragmentPassingInsideTheTurnBallIsPushedClear) {
  // Declared: 180 degrees a step, and also no bound at all (inf, the default). The region then
  // reaches R = 0.3702 m up within 3 ms (the chord rot * turn t meets the ball's cap
  // rot - 0.15 = 0.17 m) and the fragment at 0.28 m is pushed out before it arrives: it never
  // comes within its radius (less 1 mm for the steps against the solve's continuous times) of B.
  for (const double turn : {kHalfTurnPerStep_radps, kUndeclaredBound}) {
    const Flight f = fly(params(), passing(0.28), turn, kSpin_s, kCornerUp_rad);
    EXPECT_LT(f.first_push_s, kSpin_s) << turn;
    EXPECT_GT(f.closest_m, kRadius - 1e-3) << turn;
    EXPECT_LE(f.max_accel_mps2, kAMax * (1 + 1e-12)) << turn;
  }
}

TEST(EdgeMinStrategyAnyTurn, AFragmentPassingOutsideTheTurnBallIsLeftAlone) {
  // 0.5 m up: farther than R = 0.3702 m from the eye at every time, so no orientation of B can
  // reach it, however fast the turn: never even a candidate.
  for (const double turn : {kHalfTurnPerStep_radps, kUndeclaredBound}) {
    const Flight f = fly(params(), passing(0.5), turn, kSpin_s, kCornerUp_rad);
    EXPECT_FALSE(f.candidate) << turn;
    EXPECT_FALSE(f.pushed) << turn;
    EXPECT_GT(f.closest_m, 0.5 - 0.25 - 1e-9) << turn;  // B reaches 0.25 m up at most
  }
}

TEST(EdgeMinStrategyAnyTurn, AFastBoundedTurnGivesTheBallNotTheChord) {
  // 720 degrees a second. 0.45 m up, level with the eye 0.1 s from now at 10 m/s. The chord
  // bound alone would reach 0.2 + 0.3202 x 12.57 x 0.063 = 0.45 m up by the time the fragment is
  // within R in depth (0.063 s) and 0.6 m by the pass: it would hold the fragment in doubt. The
  // ball caps the reach at R = 0.3702 m: the fragment is no candidate.
  const double turn_radps = 720.0 * kPi / 180.0;
  EdgeMinStrategy s(params());
  const std::array<FragmentState, 1> frags{fragment({0.0, 0.45, -1.0}, {0, 0, 10.0})};
  StepOutput out;
  s.step(context(0.0, turn_radps, frags, 0.0, 3.0), out);
  EXPECT_TRUE(out.activity.candidates.empty());
  EXPECT_TRUE(out.forces.empty());
  // Inside the ball (0.33 m up) it is held in doubt (the constant model would leave it alone).
  const std::array<FragmentState, 1> inside{fragment({0.0, 0.33, -1.0}, {0, 0, 10.0})};
  out.clear();
  s.step(context(0.0, turn_radps, inside, 0.0, 3.0), out);
  EXPECT_EQ(out.activity.candidates.size(), 1u);
}

// Whether the path p + v t enters, at some t in [0, t_end] sampled every 1e-4 s, the region the
// chord bound alone gave (each side of B grown by the radius and rot min(turn t, 2)), widened
// by `tol_m` for the sampling.
bool enters_chord_region(const FragmentState& f, double turn_radps, double t_end_s, double tol_m) {
  for (double t = 0.0; t <= t_end_s; t += 1e-4) {
    const Eigen::Vector3d p = f.position_m + f.velocity_mps * t;
    const Eigen::Vector3d c(p.x(), p.y(), -p.z());  // camera axes: depth along -z
    const double grow = kRadius + kRot * std::min(turn_radps * t, 2.0) + tol_m;
    if (((c.cwiseAbs() - kHalf).array() <= grow).all()) return true;
  }
  return false;
}

TEST(EdgeMinStrategyAnyTurn, ABoundedTurnNeverHoldsMoreInDoubtThanTheChordAlone) {
  // Random fragments near the camera, turn rates 0 to 1,440 degrees a second, a look-ahead of
  // 0.3 s (the shot ends then). A fragment edge-min holds in doubt (a candidate) must enter the
  // chord bound's region within the look-ahead: the new region is never larger. Sampling every
  // 1e-4 s moves a path at most 2 mm (20 m/s); 5 mm is allowed.
  std::mt19937_64 rng(31);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double end_s = 0.3;
  int candidates = 0;
  int chord_only = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const double turn_radps = 12.0 * kPi * 0.5 * (1.0 + u(rng));
    const Eigen::Vector3d from(1.5 * u(rng), 1.5 * u(rng), -3.0 + 1.5 * u(rng));
    const Eigen::Vector3d aim(0.8 * u(rng), 0.8 * u(rng), 0.3 * u(rng));
    const double speed = 12.0 + 8.0 * u(rng);
    const FragmentState f = fragment(from, (aim - from).normalized() * speed);
    EdgeMinStrategy s(params());
    const std::array<FragmentState, 1> frags{f};
    StepOutput out;
    s.step(context(0.0, turn_radps, frags, 0.0, end_s), out);
    const bool chord = enters_chord_region(f, turn_radps, end_s, 5e-3);
    if (!out.activity.candidates.empty()) {
      ++candidates;
      EXPECT_TRUE(chord) << trial;
    } else if (chord) {
      ++chord_only;
    }
  }
  // Neither side empty: the test sees both kinds, and the ball spares some the chord held.
  EXPECT_GT(candidates, 0);
  EXPECT_GT(chord_only, 0);
}

TEST(EdgeMinStrategyAnyTurn, WhenTheWorstCaseCannotBeBeatenTheCapGoesTheConstantModelsWay) {
  // A camera declaring A = 80 m/s^2 > a_max and any turn: close fragments' worst cases need more
  // than a_max on every way out, so nothing is promised; the capped push then goes where the
  // constant model pushes (the likeliest camera keeps its velocity and view), at a_max. Random
  // fragments 0.4-1 m ahead at 8-12 m/s, the camera moving at up to V_c = 3 m/s.
  std::mt19937_64 rng(32);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int beaten = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const Eigen::Vector3d cam_v(3.0 * u(rng), 3.0 * u(rng), 0.0);
    const FragmentState f =
        fragment({0.15 * u(rng), 0.15 * u(rng), -0.7 + 0.3 * u(rng)},
                 Eigen::Vector3d(cam_v.x() + u(rng), cam_v.y() + u(rng), 10.0 + 2.0 * u(rng)));
    const std::array<FragmentState, 1> frags{f};
    StepContext ctx = context(0.0, kUndeclaredBound, frags, 0.0, 3.0);
    ctx.camera_velocity_mps = cam_v.cwiseMin(3.0 / std::sqrt(2.0)).cwiseMax(-3.0 / std::sqrt(2.0));
    ctx.camera_max_speed_mps = 3.0;
    ctx.camera_max_accel_mps2 = 80.0;
    EdgeMinStrategy bounded(params());
    EdgeMinStrategy constant(params(CameraModel::kConstant));
    StepOutput b;
    StepOutput c;
    bounded.step(ctx, b);
    constant.step(ctx, c);
    if (b.activity.capped.empty() || c.forces.empty()) continue;
    ++beaten;
    ASSERT_EQ(b.forces.size(), 1u);
    const Eigen::Vector3d fb = b.forces[0].force_N;
    const Eigen::Vector3d fc = c.forces[0].force_N;
    // The same way (one of +-right, +-up: parallel unit vectors), at the cap.
    EXPECT_NEAR(fb.normalized().dot(fc.normalized()), 1.0, 1e-12) << trial;
    EXPECT_NEAR(fb.norm() / f.mass_kg, kAMax, 1e-9) << trial;
  }
  EXPECT_GT(beaten, 20);
}

}  // namespace
}  // namespace fragsim
