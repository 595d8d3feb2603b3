// `edge-min`'s camera models (docs/camera_models.md), driven directly through StepContext with a
// hand-integrated loop (semi-implicit Euler, as ODE steps): no world, no ODE.
//
// The camera sits at the origin looking down -z (right = +x, up = +y) with the default frustum
// (near 0.1 m, 60 degrees, 16:9) and a 0.3 x 0.2 x 0.3 m body; margin 0.05 m. The protected box
// is then 0.2 m to each side, 0.15 m up and down and 0.2 m in depth each way, before the
// fragment's radius (0.05 m here). Unless a test says otherwise the turn rate is 0 (the view does
// not turn), so the grown box is only 0.5 A t^2 (bounded_accel) or V_c t (reachable) wider.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "control/strategies/edge_min_strategy.hpp"

namespace fragsim {
namespace {

constexpr double kDt = 1.0 / 60.0;
constexpr double kRadius = 0.05;
constexpr double kAMax = 50.0;
constexpr double kA = 20.0;
constexpr double kVc = 3.0;
// The protected box grown by the fragment's radius.
constexpr double kHalfX = 0.2 + kRadius;
constexpr double kHalfY = 0.15 + kRadius;
constexpr double kHalfZ = 0.2 + kRadius;

EdgeMinParams params(CameraModel model, double turn_degps = 0.0) {
  EdgeMinParams p;
  p.camera_model = model;
  p.a_max_mps2 = kAMax;
  p.camera_accel_mps2 = kA;
  p.camera_turn_degps = turn_degps;
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

// One step's context: a still-oriented camera at `eye_m` moving at `cam_v_mps` over the step.
StepContext context(const Eigen::Vector3d& eye_m, const Eigen::Vector3d& cam_v_mps,
                    std::span<const FragmentState> fragments, double t_s = 0.0,
                    double duration_s = 3.0) {
  StepContext ctx;
  ctx.t_s = t_s;
  ctx.dt_s = kDt;
  ctx.end_time_s = duration_s;  // the shot's end, as the old scene duration
  ctx.camera.eye_m = eye_m;
  ctx.camera_velocity_mps = cam_v_mps;
  ctx.camera_max_speed_mps = kVc;
  ctx.camera_body_half_m = {0.15, 0.1, 0.15};
  ctx.fragments = fragments;
  return ctx;
}

// The acceleration the strategy imposes on fragment 0 this step (zero when none).
Eigen::Vector3d accel_of(const StepOutput& out, double mass_kg) {
  for (const AppliedForce& f : out.forces) {
    if (f.fragment == 0) return f.force_N / mass_kg;
  }
  return Eigen::Vector3d::Zero();
}

// How deep the fragment's centre is inside the protected box (<= 0: outside).
double depth_in_box(const Eigen::Vector3d& rel_m) {
  return std::min(
      {kHalfX - std::abs(rel_m.x()), kHalfY - std::abs(rel_m.y()), kHalfZ - std::abs(rel_m.z())});
}

// The push aims at the box's edge itself, so a saved fragment may graze it: "entered" allows
// 1 mm (a fiftieth of the margin) for the steps' positions against the solve's continuous times.
constexpr double kGraze_m = 1e-3;

// A camera that moves by a rule of its own (given the fragment and the time), integrated with the
// fragment under `model` for `steps`: whether the fragment's centre ever entered the protected
// box, and the largest imposed acceleration. Camera velocity is updated first: the strategy sees
// the velocity of the step being taken, as in the simulation.
struct LoopResult {
  bool entered = false;
  double depth_m = 0.0;  // deepest inside the box
  double max_accel_mps2 = 0.0;
  bool finite = true;
};
template <class CameraRule>
LoopResult run_loop(const EdgeMinParams& p, FragmentState f, CameraRule rule, int steps,
                    double declared_accel_mps2 = kUndeclaredBound) {
  EdgeMinStrategy strategy(p);
  strategy.reset(1);
  Eigen::Vector3d eye = Eigen::Vector3d::Zero();
  Eigen::Vector3d cam_v = Eigen::Vector3d::Zero();
  LoopResult res;
  StepOutput out;
  for (int k = 0; k < steps; ++k) {
    const double t = k * kDt;
    cam_v = rule(t, eye, cam_v, f);
    std::array<FragmentState, 1> frags{f};
    StepContext ctx = context(eye, cam_v, frags, t, steps * kDt);
    ctx.camera_max_accel_mps2 = declared_accel_mps2;
    out.clear();
    strategy.step(ctx, out);
    const Eigen::Vector3d a = accel_of(out, f.mass_kg);
    res.finite = res.finite && a.allFinite();
    res.max_accel_mps2 = std::max(res.max_accel_mps2, a.norm());
    f.velocity_mps += a * kDt;
    f.position_m += f.velocity_mps * kDt;
    eye += cam_v * kDt;
    // Camera axes are the world's: the box is axis-aligned about the eye.
    res.depth_m = std::max(res.depth_m, depth_in_box(f.position_m - eye));
    res.entered = res.depth_m > kGraze_m;
  }
  return res;
}

// Accelerate at `a_mps2` along y toward the fragment once `start_s` has passed, up to V_c.
auto pursue(double a_mps2, double start_s) {
  return [a_mps2, start_s](double t, const Eigen::Vector3d& eye, Eigen::Vector3d v,
                           const FragmentState& f) {
    if (t < start_s) return v;
    const double toward = f.position_m.y() > eye.y() ? 1.0 : -1.0;
    v.y() += toward * a_mps2 * kDt;
    v.y() = std::clamp(v.y(), -kVc, kVc);
    return v;
  };
}

TEST(EdgeMinCameraModel, BoundedAccelAddsToTheConstantPushOnlyOnceWaitingIsUnsafe) {
  // Dead centre at 10 m/s. Place the fragment so that it reaches the grown box's front face
  // (depth kHalfZ + 0.5 A tau^2) tau after now. The worst case's gap on the nearer side is then
  // kHalfY + 0.5 A tau^2 and a push started a step later moves it 0.5 tau (tau - dt) per unit,
  // so waiting is unsafe once 0.5 (a_max - A) tau^2 - 0.5 a_max dt tau > kHalfY:
  //   15 tau^2 - 0.4167 tau - 0.2 = 0  ->  tau* = 0.1302 s.
  const double tau_star = (0.5 * kAMax * kDt + std::sqrt(std::pow(0.5 * kAMax * kDt, 2) +
                                                         4.0 * 0.5 * (kAMax - kA) * kHalfY)) /
                          (2.0 * 0.5 * (kAMax - kA));
  ASSERT_NEAR(tau_star, 0.1302, 1e-4);
  EdgeMinStrategy constant(params(CameraModel::kConstant));
  EdgeMinStrategy bounded(params(CameraModel::kBoundedAccel));
  double switch_tau = -1.0;
  for (double tau = 0.40; tau > 0.03; tau -= 0.001) {
    const double z0 = kHalfZ + 0.5 * kA * tau * tau + 10.0 * tau;
    const std::array<FragmentState, 1> frags{fragment({0, 0, -z0}, {0, 0, 10.0})};
    const StepContext ctx = context(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), frags);
    StepOutput c;
    StepOutput b;
    constant.step(ctx, c);
    bounded.step(ctx, b);
    const Eigen::Vector3d ac = accel_of(c, 2.0);
    const Eigen::Vector3d ab = accel_of(b, 2.0);
    // The constant model always pushes this fragment (it is headed for the lens).
    ASSERT_GT(ac.norm(), 0.0) << tau;
    if (switch_tau < 0.0 && (ab - ac).norm() > 1e-9) switch_tau = tau;
    if (switch_tau < 0.0) {
      EXPECT_EQ(ab, ac) << "lazy: the constant push while waiting is safe, tau " << tau;
    } else {
      // Once waiting is unsafe: the worst case's push along the same way out, more than the
      // constant one, at most a_max.
      EXPECT_GE(ab.norm(), ac.norm() - 1e-9) << tau;
      EXPECT_LE(ab.norm(), kAMax * (1 + 1e-12)) << tau;
    }
  }
  // Found to the scan's millisecond, plus one step: the worst case's need is sampled (its largest
  // is at the entry time here, a sample) and the grown z-slab's entry is solved exactly.
  EXPECT_NEAR(switch_tau, tau_star, kDt);
  // The textbook condition 0.5 (a_max - A) tau^2 = kHalfY (no one-step delay) is within a step.
  EXPECT_NEAR(std::sqrt(kHalfY / (0.5 * (kAMax - kA))), switch_tau, kDt);
}

TEST(EdgeMinCameraModel, AClearMissIsPushedUnderNoModel) {
  // 2 m above the axis, flying past at 10 m/s, 1 s away: more than any grown box within the
  // look-ahead (reachable: V_c t = 0.7 m at 0.24 s; bounded: 0.5 A t^2 = 0.2 m at 0.15 s), even
  // with the default 90 degrees/s turn (0.32 m x 0.4 rad).
  for (CameraModel m :
       {CameraModel::kConstant, CameraModel::kBoundedAccel, CameraModel::kReachable}) {
    for (double turn : {0.0, 90.0}) {
      EdgeMinStrategy s(params(m, turn));
      for (double z0 : {10.0, 3.0, 1.0, 0.5}) {
        const std::array<FragmentState, 1> frags{fragment({0, 2.0, -z0}, {0, 0, 10.0})};
        StepOutput out;
        s.step(context(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), frags), out);
        EXPECT_TRUE(out.forces.empty()) << static_cast<int>(m) << " " << turn << " " << z0;
        EXPECT_TRUE(out.activity.candidates.empty())
            << static_cast<int>(m) << " " << turn << " " << z0;
      }
    }
  }
}

TEST(EdgeMinCameraModel, BoundedAccelSavesAFragmentFromACameraThatSwervesIntoIt) {
  // The fragment would pass 0.35 m above the eye (0.15 m clear of the box) 0.78 s from now. The
  // camera holds still, then at t = 0.62 accelerates upward at 20 (declared; speed capped
  // at V_c) after the fragment.
  const double a_cam = 30.0;
  const double start_s = 0.45;
  EdgeMinParams p = params(CameraModel::kBoundedAccel);
  p.camera_accel_mps2 = a_cam;
  const FragmentState f = fragment({0, 0.35, -8.0}, {0, 0, 10.0});
  const int steps = 70;
  const LoopResult constant =
      run_loop(params(CameraModel::kConstant), f, pursue(a_cam, start_s), steps);
  EXPECT_GT(constant.depth_m, 0.02) << "the constant model cannot foresee the swerve";
  const LoopResult bounded = run_loop(p, f, pursue(a_cam, start_s), steps, a_cam);
  EXPECT_FALSE(bounded.entered);
  EXPECT_LE(bounded.max_accel_mps2, kAMax * (1 + 1e-12));
  // Reachable assumes more (any acceleration): it saves it too.
  p.camera_model = CameraModel::kReachable;
  EXPECT_FALSE(run_loop(p, f, pursue(a_cam, start_s), steps, a_cam).entered);
}

TEST(EdgeMinCameraModel, ReachableSavesAFragmentFromACameraThatJumpsToFullSpeed) {
  // A player camera with instant turns: velocity jumps to V_c toward the fragment 0.2 s before
  // the pass. bounded_accel (assuming A = 20) is not promised anything; reachable is.
  const FragmentState f = fragment({0, 0.35, -8.0}, {0, 0, 10.0});
  const auto jump = [](double t, const Eigen::Vector3d& eye, Eigen::Vector3d v,
                       const FragmentState& frag) {
    if (t >= 0.6) v.y() = frag.position_m.y() > eye.y() ? kVc : -kVc;
    return v;
  };
  EXPECT_TRUE(run_loop(params(CameraModel::kConstant), f, jump, 70).entered);
  const LoopResult reachable = run_loop(params(CameraModel::kReachable), f, jump, 70);
  EXPECT_FALSE(reachable.entered);
  EXPECT_TRUE(reachable.finite);
}

TEST(EdgeMinCameraModel, RandomSwervingCamerasWithinTheBoundsNeverGetHit) {
  // Fragments from random directions and offsets at 6-14 m/s, with gravity off, against a camera
  // whose acceleration (|a| <= A per axis component along x and y, so |a| <= A after scaling) is
  // redrawn every 0.05-0.3 s, speed capped at V_c. This checks what is sampled rather than
  // proven: nine samples per interval, the look-ahead window, the far-side gaps.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int saved = 0;
  const int trials = 150;
  for (int trial = 0; trial < trials; ++trial) {
    const double speed = 10.0 + 4.0 * u(rng);
    const Eigen::Vector3d aim(0.3 * u(rng), 0.3 * u(rng), 0.0);
    const Eigen::Vector3d from(1.5 * u(rng), 1.5 * u(rng), -6.0 - 2.0 * u(rng));
    const FragmentState f = fragment(from, (aim - from).normalized() * speed);
    std::mt19937 cam_rng(static_cast<unsigned>(100 + trial));
    Eigen::Vector3d accel = Eigen::Vector3d::Zero();
    double next_change = 0.0;
    const auto rule = [&](double t, const Eigen::Vector3d&, Eigen::Vector3d v,
                          const FragmentState&) {
      if (t >= next_change) {
        std::uniform_real_distribution<double> c(-1.0, 1.0);
        accel = Eigen::Vector3d(c(cam_rng), c(cam_rng), 0.0);
        if (accel.norm() > 1.0) accel.normalize();
        accel *= kA;
        next_change = t + 0.05 + 0.25 * 0.5 * (1.0 + c(cam_rng));
      }
      v += accel * kDt;
      if (v.norm() > kVc) v *= kVc / v.norm();
      return v;
    };
    const LoopResult r = run_loop(params(CameraModel::kBoundedAccel), f, rule, 90, kA);
    EXPECT_FALSE(r.entered) << "trial " << trial;
    EXPECT_TRUE(r.finite);
    saved += r.entered ? 0 : 1;
  }
  EXPECT_EQ(saved, trials);
}

TEST(EdgeMinCameraModel, ACameraAboveTheBoundGetsTheCapNotNaN) {
  // A = 80 m/s^2 declared, a_max = 50: no push can promise a miss against a late swerve. The push
  // grows toward the cap (the camera reaches V_c within 0.04 s, which limits what it needs),
  // stays finite, and the loop runs on.
  const FragmentState f = fragment({0, 0.35, -8.0}, {0, 0, 10.0});
  const LoopResult r =
      run_loop(params(CameraModel::kBoundedAccel), f, pursue(80.0, 0.55), 70, 80.0);
  EXPECT_TRUE(r.finite);
  EXPECT_LE(r.max_accel_mps2, kAMax * (1 + 1e-12));
  EXPECT_GT(r.max_accel_mps2, 0.5 * kAMax);
  // And the strategy reports the capped push.
  EdgeMinStrategy s(params(CameraModel::kBoundedAccel));
  const std::array<FragmentState, 1> frags{fragment({0, 0, -0.6}, {0, 0, 10.0})};
  StepContext ctx = context(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), frags);
  ctx.camera_max_accel_mps2 = 80.0;
  StepOutput out;
  s.step(ctx, out);
  ASSERT_EQ(out.forces.size(), 1u);
  EXPECT_TRUE(out.forces[0].force_N.allFinite());
  EXPECT_EQ(out.activity.capped.size(), 1u);
}

TEST(EdgeMinCameraModel, UndeclaredBoundsFallBackToTheParameters) {
  EdgeMinParams p = params(CameraModel::kBoundedAccel, 90.0);
  const EdgeMinStrategy s(p);
  const std::array<FragmentState, 1> frags{fragment({0, 0, -5}, {0, 0, 10.0})};
  StepContext ctx = context(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), frags);
  for (double undeclared : {kUndeclaredBound, -0.5, std::numeric_limits<double>::quiet_NaN()}) {
    ctx.camera_max_accel_mps2 = undeclared;
    ctx.camera_max_turn_degps = undeclared;
    EXPECT_EQ(s.assumed_accel_mps2(ctx), kA);
    EXPECT_NEAR(s.assumed_turn_radps(ctx), 0.5 * kPi, 1e-15);
  }
  // 0 is a bound, not "undeclared": a camera that cannot accelerate or turn.
  ctx.camera_max_accel_mps2 = 0.0;
  ctx.camera_max_turn_degps = 0.0;
  EXPECT_EQ(s.assumed_accel_mps2(ctx), 0.0);
  EXPECT_EQ(s.assumed_turn_radps(ctx), 0.0);
  ctx.camera_max_accel_mps2 = 7.0;
  ctx.camera_max_turn_degps = 45.0;
  EXPECT_EQ(s.assumed_accel_mps2(ctx), 7.0);
  EXPECT_NEAR(s.assumed_turn_radps(ctx), 0.25 * kPi, 1e-15);
}

// A player with instant turns declares an infinite acceleration: bounded_accel then keeps only
// the ball V_c t, which is exactly reachable's region, so the two give the same forces.
TEST(EdgeMinCameraModel, DeclaredInfiniteAccelerationIsTheReachableBall) {
  EdgeMinStrategy bounded(params(CameraModel::kBoundedAccel, 90.0));
  EdgeMinStrategy reachable(params(CameraModel::kReachable, 90.0));
  const std::array<FragmentState, 3> frags{fragment({0, 0, -5}, {0, 0, 10.0}),
                                           fragment({0.3, 0.1, -3}, {-0.5, 0, 9.0}),
                                           fragment({0, -0.2, -2}, {0, 0.4, 11.0})};
  StepContext ctx = context(Eigen::Vector3d::Zero(), Eigen::Vector3d(0.5, 0, 0), frags);
  ctx.camera_max_accel_mps2 = std::numeric_limits<double>::infinity();
  ctx.camera_max_turn_degps = 90.0;
  int pushed = 0;
  for (double t : {0.0, 0.2, 0.25, 0.3}) {
    ctx.t_s = t;
    StepOutput a, b;
    bounded.step(ctx, a);
    reachable.step(ctx, b);
    ASSERT_EQ(a.forces.size(), b.forces.size());
    for (std::size_t i = 0; i < a.forces.size(); ++i) {
      EXPECT_EQ(a.forces[i].fragment, b.forces[i].fragment);
      EXPECT_EQ(a.forces[i].force_N, b.forces[i].force_N);
      EXPECT_TRUE(a.forces[i].force_N.allFinite());
    }
    pushed += static_cast<int>(a.forces.size());
  }
  EXPECT_GT(pushed, 0);
}

TEST(EdgeMinCameraModel, WithAConstantCameraAndFarThreatsBoundedAccelIsTheConstantModel) {
  // The camera really keeps its velocity (1 m/s sideways); fragments 1-1.4 s away, some headed
  // at it. While no worst case is inside the look-ahead window, bounded_accel must apply exactly
  // the constant model's forces.
  std::vector<FragmentState> frags;
  for (int i = 0; i < 6; ++i) {
    const double z0 = 10.0 + 0.8 * i;
    frags.push_back(fragment({0.05 * i - 0.1 + 1.0 * z0 / 10.0, 0.02 * i, -z0}, {0, 0, 10.0}));
  }
  EdgeMinStrategy constant(params(CameraModel::kConstant, 90.0));
  EdgeMinStrategy bounded(params(CameraModel::kBoundedAccel, 90.0));
  const Eigen::Vector3d cam_v(1.0, 0.0, 0.0);
  Eigen::Vector3d eye = Eigen::Vector3d::Zero();
  int pushes = 0;
  // 0.6 s: the nearest fragment is still 0.4 s away, beyond the look-ahead (~0.2 s).
  for (int k = 0; k < 36; ++k) {
    const StepContext ctx = context(eye, cam_v, frags, k * kDt);
    StepOutput c;
    StepOutput b;
    constant.step(ctx, c);
    bounded.step(ctx, b);
    ASSERT_EQ(c.forces.size(), b.forces.size()) << k;
    for (std::size_t j = 0; j < c.forces.size(); ++j) {
      EXPECT_EQ(c.forces[j].fragment, b.forces[j].fragment);
      EXPECT_EQ(c.forces[j].force_N, b.forces[j].force_N) << "step " << k;
    }
    pushes += static_cast<int>(c.forces.size());
    for (const AppliedForce& a : c.forces) {
      FragmentState& f = frags[static_cast<std::size_t>(a.fragment)];
      f.velocity_mps += a.force_N / f.mass_kg * kDt;
    }
    for (FragmentState& f : frags) f.position_m += f.velocity_mps * kDt;
    eye += cam_v * kDt;
  }
  EXPECT_GT(pushes, 0) << "the constant model had threats to push";
}

}  // namespace
}  // namespace fragsim
