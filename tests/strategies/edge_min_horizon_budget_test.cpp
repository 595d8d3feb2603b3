// `edge-min`'s look-ahead from the physics (a path is examined until the fragment reaches the
// ground, capped by horizon_cap_s) and its per-step budget (max_solves), on hand-built steps.
// Camera: the default pose (eye at the origin, looking down -z, near 0.1 m), body 0.15 x 0.1 x
// 0.15 m half-size, margin 0.05 m: the protected box reaches 0.2 m + r to the sides, 0.15 m + r
// up and down, and 0.2 m + r in front of the eye.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "control/strategies/edge_min_strategy.hpp"
#include "fragsim/control.h"

namespace fragsim {
namespace {

constexpr double kDt = 1.0 / 60.0;
constexpr double kInf = std::numeric_limits<double>::infinity();

FragmentState fragment(const Eigen::Vector3d& p_m, const Eigen::Vector3d& v_mps) {
  FragmentState f;
  f.position_m = p_m;
  f.velocity_mps = v_mps;
  f.radius_m = 0.05;
  f.mass_kg = 2.0;
  return f;
}

StepContext context(std::span<const FragmentState> fragments, double gravity_y_mps2,
                    double ground_m) {
  StepContext ctx;
  ctx.dt_s = kDt;
  ctx.camera_max_speed_mps = 3.0;
  ctx.camera_body_half_m = {0.15, 0.1, 0.15};
  ctx.gravity_mps2 = {0.0, gravity_y_mps2, 0.0};
  ctx.ground_height_m = ground_m;
  ctx.fragments = fragments;
  return ctx;
}

const AppliedForce* force_on(const StepOutput& out, int i) {
  for (const AppliedForce& f : out.forces) {
    if (f.fragment == i) return &f;
  }
  return nullptr;
}

EdgeMinParams constant_model() {
  EdgeMinParams p;
  p.camera_model = CameraModel::kConstant;
  return p;
}

// y(t) = 0.1 - 4.905 t^2 reaches 0.05 (the ground plus the radius) at sqrt(0.05 / 4.905).
TEST(EdgeMinHorizonBudget, TimeToGroundIsTheLaterDownwardRoot) {
  EXPECT_NEAR(EdgeMinStrategy::time_to_ground_s(0.1, 0.0, -4.905, 0.05), 0.1009636, 1e-6);
  // Thrown up at 4.905 m/s from the ground's height: back down through it at t = 1 s.
  EXPECT_NEAR(EdgeMinStrategy::time_to_ground_s(0.05, 4.905, -4.905, 0.05), 1.0, 1e-12);
  // No ground, or no gravity and not falling: it never comes down.
  EXPECT_EQ(EdgeMinStrategy::time_to_ground_s(1.0, 0.0, -4.905, -kInf), kInf);
  EXPECT_EQ(EdgeMinStrategy::time_to_ground_s(1.0, 0.0, 0.0, 0.0), kInf);
  // Zero gravity, falling at 2 m/s from 1 m above: 0.5 s.
  EXPECT_NEAR(EdgeMinStrategy::time_to_ground_s(1.0, -2.0, 0.0, 0.0), 0.5, 1e-15);
  // Resting on the ground (sunk 1 mm into it): nothing ahead.
  EXPECT_EQ(EdgeMinStrategy::time_to_ground_s(0.049, 0.0, -4.905, 0.05), 0.0);
}

// A camera skimming the floor (eye 0.12 m up, its box reaching 0.2 m below the eye, into the
// ground) and a fragment sliding in 0.1 m up at 30 m/s from 5 m ahead. It touches the ground
// (y = 0.05) after 0.101 s, 1.97 m ahead of the eye; the ballistic path, continued underground,
// would enter the box's front (depth 0.25 m) at t = 4.75 / 30 = 0.158 s at y = 0.1 - 4.905 *
// 0.158^2 = -0.023 m, inside the box's [-0.08, 0.32] m. It bounces before that: no push. With
// no ground, or the ground 10 m below, the path is examined for the whole 3 s: pushed.
TEST(EdgeMinHorizonBudget, APathThatHitsTheGroundFirstIsNotPushed) {
  const std::vector<FragmentState> frags{fragment({0.0, 0.1, -5.0}, {0.0, 0.0, 30.0})};
  for (double ground_m : {0.0, -10.0, -kInf}) {
    EdgeMinStrategy s(constant_model());
    s.reset(1);
    StepContext ctx = context(frags, -9.81, ground_m);
    ctx.camera.eye_m = {0.0, 0.12, 0.0};
    StepOutput out;
    s.step(ctx, out);
    const bool pushed = force_on(out, 0) != nullptr;
    EXPECT_EQ(pushed, ground_m < 0.0) << "ground at " << ground_m;
  }
}

// The cap bounds the look-ahead when nothing comes down: zero gravity, a fragment 40.25 m ahead
// at 10 m/s reaches the box (0.25 m in front of the eye) at t = 4 s.
TEST(EdgeMinHorizonBudget, TheCapBoundsAPathThatNeverComesDown) {
  const std::vector<FragmentState> frags{fragment({0.0, 0.02, -40.25}, {0.0, 0.0, 10.0})};
  for (double cap_s : {3.0, 5.0}) {
    EdgeMinParams p = constant_model();
    p.horizon_cap_s = cap_s;
    EdgeMinStrategy s(p);
    s.reset(1);
    StepOutput out;
    s.step(context(frags, 0.0, -kInf), out);
    EXPECT_EQ(force_on(out, 0) != nullptr, cap_s > 4.0) << "cap " << cap_s;
  }
}

// Three threats on the view axis, zero gravity, arrival time |d|^2 / (-d . w):
//   0: 4 m ahead at 2 m/s, 2 s;  1: 6 m ahead at 12 m/s, 0.5 s;  2: 3 m ahead at 1 m/s, 3 s
// (the nearest in distance, the last in time). A 5 s cap sees all three.
std::vector<FragmentState> three_threats() {
  return {fragment({0.0, 0.02, -4.0}, {0.0, 0.0, 2.0}),
          fragment({0.03, 0.0, -6.0}, {0.0, 0.0, 12.0}),
          fragment({0.0, -0.02, -3.0}, {0.0, 0.0, 1.0})};
}

TEST(EdgeMinHorizonBudget, TheCapSolvesTheSoonestToArriveAndDefersTheRest) {
  const std::vector<FragmentState> frags = three_threats();
  EdgeMinParams p = constant_model();
  p.horizon_cap_s = 5.0;
  {
    EdgeMinStrategy all(p);
    all.reset(3);
    StepOutput out;
    all.step(context(frags, 0.0, -kInf), out);
    ASSERT_EQ(out.forces.size(), 3u);  // all three need a push without the budget
    EXPECT_EQ(out.activity.deferred, 0);
  }
  p.max_solves = 1;
  EdgeMinStrategy s(p);
  s.reset(3);
  StepOutput out;
  s.step(context(frags, 0.0, -kInf), out);
  EXPECT_EQ(out.activity.deferred, 2);
  ASSERT_EQ(out.forces.size(), 1u);  // the deferred two were never solved: no last force
  EXPECT_EQ(out.forces[0].fragment, 1);
  EXPECT_EQ(std::vector<int>(out.activity.candidates.begin(), out.activity.candidates.end()),
            std::vector<int>{1});
}

// A deferred fragment keeps the force of the last step it was solved, to the bit.
TEST(EdgeMinHorizonBudget, ADeferredFragmentKeepsItsLastForce) {
  EdgeMinParams p = constant_model();
  p.horizon_cap_s = 5.0;
  p.max_solves = 1;
  EdgeMinStrategy s(p);
  s.reset(2);
  std::vector<FragmentState> frags{fragment({0.0, 0.02, -4.0}, {0.0, 0.0, 2.0}),
                                   fragment({0.03, 0.0, -6.0}, {0.0, 0.0, 12.0})};
  StepOutput out;
  s.step(context(frags, 0.0, -kInf), out);  // 1 is sooner: 0 deferred, never solved
  EXPECT_EQ(out.activity.deferred, 1);
  EXPECT_EQ(force_on(out, 0), nullptr);
  frags[1].velocity_mps = {0.0, 0.0, -12.0};  // 1 turns away: rejected cheaply, 0 is solved
  out.clear();
  s.step(context(frags, 0.0, -kInf), out);
  EXPECT_EQ(out.activity.deferred, 0);
  ASSERT_NE(force_on(out, 0), nullptr);
  const Eigen::Vector3d solved_N = force_on(out, 0)->force_N;
  frags[1].velocity_mps = {0.0, 0.0, 12.0};  // 1 comes back: solved, 0 deferred again
  out.clear();
  s.step(context(frags, 0.0, -kInf), out);
  EXPECT_EQ(out.activity.deferred, 1);
  ASSERT_NE(force_on(out, 0), nullptr);
  EXPECT_EQ(force_on(out, 0)->force_N, solved_N);
  EXPECT_NE(force_on(out, 1), nullptr);
}

// With no cap (0) or a cap above the number of survivors, the same forces to the bit, over a
// few steps of 64 fragments under gravity with the default (bounded_accel) model.
TEST(EdgeMinHorizonBudget, ACapNeverReachedChangesNothing) {
  std::vector<FragmentState> frags;
  for (int i = 0; i < 64; ++i) {
    const double s = 0.1 * (i % 8) - 0.35;
    const double u = 0.1 * (i / 8) - 0.35;
    frags.push_back(fragment({s, 1.6 + u, -6.0 - 0.05 * i}, {-0.3 * s, 2.0 - u, 9.0 + 0.1 * i}));
  }
  EdgeMinParams capped;
  capped.max_solves = 1000;
  EdgeMinStrategy a{EdgeMinParams{}};
  EdgeMinStrategy b{capped};
  a.reset(64);
  b.reset(64);
  int pushed = 0;
  for (int step = 0; step < 5; ++step) {
    StepContext ctx = context(frags, -9.81, 0.0);
    ctx.t_s = step * kDt;
    ctx.camera.eye_m = {0.0, 1.6, -0.5};
    ctx.camera_velocity_mps = {0.0, 0.0, -2.0};
    StepOutput oa, ob;
    a.step(ctx, oa);
    b.step(ctx, ob);
    ASSERT_EQ(oa.forces.size(), ob.forces.size());
    for (std::size_t k = 0; k < oa.forces.size(); ++k) {
      EXPECT_EQ(oa.forces[k].fragment, ob.forces[k].fragment);
      EXPECT_EQ(
          std::memcmp(oa.forces[k].force_N.data(), ob.forces[k].force_N.data(), 3 * sizeof(double)),
          0);
    }
    EXPECT_EQ(oa.activity.candidates, ob.activity.candidates);
    EXPECT_EQ(ob.activity.deferred, 0);
    pushed += static_cast<int>(oa.forces.size());
    for (FragmentState& f : frags) {
      f.velocity_mps.y() -= 9.81 * kDt;
      f.position_m += f.velocity_mps * kDt;
    }
  }
  EXPECT_GT(pushed, 0);
}

// The C API: the def's max_solves reaches the strategy, the deferred count comes back in the
// stats, a deferred fragment's last force is kept by id, and a negative cap is refused.
TEST(EdgeMinHorizonBudget, TheControllerReportsDeferredFragments) {
  fragsim_controller_def def = fragsim_default_controller_def();
  EXPECT_EQ(def.edge_min.max_solves, 0);
  def.edge_min.camera_model = FRAGSIM_CAMERA_CONSTANT;
  def.horizon_cap_s = 5.0;
  def.edge_min.max_solves = -1;
  fragsim_controller_id ctl{};
  char message[256];
  EXPECT_EQ(fragsim_controller_create(&def, &ctl, message, sizeof message),
            FRAGSIM_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(message).find("edge_min.max_solves"), std::string::npos) << message;
  def.edge_min.max_solves = 1;
  ASSERT_EQ(fragsim_controller_create(&def, &ctl, message, sizeof message), FRAGSIM_OK) << message;

  std::vector<fragsim_fragment> frags;
  std::uint64_t id = 100;
  for (const FragmentState& s : three_threats()) {
    fragsim_fragment f{};
    f.position_m = {s.position_m.x(), s.position_m.y(), s.position_m.z()};
    f.velocity_mps = {s.velocity_mps.x(), s.velocity_mps.y(), s.velocity_mps.z()};
    f.radius_m = s.radius_m;
    f.mass_kg = s.mass_kg;
    f.id = id++;
    frags.push_back(f);
  }
  const fragsim_camera_def camera = fragsim_default_camera_def();
  ASSERT_EQ(fragsim_controller_set_cameras(ctl, &camera, 1), FRAGSIM_OK);
  const fragsim_camera_pose pose = fragsim_default_camera_pose();
  fragsim_step_input in = fragsim_default_step_input();
  in.dt_s = kDt;
  in.gravity_mps2 = {0.0, 0.0, 0.0};
  in.camera_poses = &pose;
  in.camera_count = 1;
  std::vector<fragsim_vec3> forces(3);
  fragsim_step_stats stats{};
  ASSERT_EQ(fragsim_controller_step(ctl, &in, frags.data(), 3, forces.data(), &stats), FRAGSIM_OK)
      << fragsim_controller_last_error(ctl);
  EXPECT_EQ(stats.deferred, 2);
  EXPECT_EQ(stats.pushed, 1);
  EXPECT_GT(forces[1].y * forces[1].y + forces[1].x * forces[1].x, 0.0);
  const fragsim_vec3 solved = forces[1];

  // Reordered, and id 101 (the urgent one) now outranked by a new id at 1 m, 10 m/s (0.1 s):
  // 101 is deferred and keeps its force from the first call, found by id.
  std::vector<fragsim_fragment> next{frags[2], frags[1], frags[0]};
  fragsim_fragment fast = frags[0];
  fast.position_m = {0.0, 0.03, -1.0};
  fast.velocity_mps = {0.0, 0.0, 10.0};
  fast.id = 7;
  next.push_back(fast);
  forces.assign(4, fragsim_vec3{});
  ASSERT_EQ(fragsim_controller_step(ctl, &in, next.data(), 4, forces.data(), &stats), FRAGSIM_OK)
      << fragsim_controller_last_error(ctl);
  EXPECT_EQ(stats.deferred, 3);
  EXPECT_EQ(std::memcmp(&forces[1], &solved, sizeof solved), 0);
  EXPECT_EQ(stats.pushed, 2);  // the new one and 101's kept force
  fragsim_controller_destroy(ctl);
}

}  // namespace
}  // namespace fragsim
