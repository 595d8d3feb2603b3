// The controller library's C API (fragsim/control.h): defaults, refusals with a status and
// a message, forces equal to the tool's strategies', state kept by fragment id.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "control/geometry/frustum.hpp"
#include "control/strategies/deflect_all_strategy.hpp"
#include "control/strategies/edge_min_strategy.hpp"
#include "control/strategies/edge_strategy.hpp"
#include "fragsim/control.h"

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kDt = 1.0 / 60.0;

struct Controller {
  fragsim_controller_id ctl{};
  explicit Controller(const fragsim_controller_def& def) {
    char message[256];
    const fragsim_status s = fragsim_controller_create(&def, &ctl, message, sizeof message);
    EXPECT_EQ(s, FRAGSIM_OK) << message;
  }
  ~Controller() { fragsim_controller_destroy(ctl); }
};

// A camera whole, its constants and its pose in one struct, as the tests write it; split into
// fragsim_camera_def and fragsim_camera_pose at each step.
struct WholeCamera {
  fragsim_vec3 eye_m, right, up, forward, velocity_mps;
  double fovy_deg, aspect, near_m, far_m;
  fragsim_vec3 body_half_m;
  double max_speed_mps, max_accel_mps2, max_turn_degps;
};

WholeCamera default_camera() {
  const fragsim_camera_def d = fragsim_default_camera_def();
  const fragsim_camera_pose p = fragsim_default_camera_pose();
  return {p.eye_m,         p.right,  p.up,    p.forward,     p.velocity_mps,  d.fovy_deg,
          d.aspect,        d.near_m, d.far_m, d.body_half_m, d.max_speed_mps, d.max_accel_mps2,
          d.max_turn_degps};
}

// A step's input with its camera and fragments, as the tests change them.
struct TestInput : fragsim_step_input {
  WholeCamera camera;
  const fragsim_fragment* fragments = nullptr;
  int32_t fragment_count = 0;
  fragsim_camera_pose pose{};
};

// Sets the camera's constants (they survive between steps; setting them again changes nothing of
// the fragments' state) and steps with its pose. A refused set_cameras is answered as a refused
// step would be: zero forces and stats.
fragsim_status step_with(fragsim_controller_id ctl, TestInput* in, fragsim_vec3* forces,
                         fragsim_step_stats* stats) {
  if (in != nullptr) {
    const WholeCamera& c = in->camera;
    const fragsim_camera_def d{c.fovy_deg,    c.aspect,        c.near_m,         c.far_m,
                               c.body_half_m, c.max_speed_mps, c.max_accel_mps2, c.max_turn_degps};
    const fragsim_status s = fragsim_controller_set_cameras(ctl, &d, 1);
    if (s != FRAGSIM_OK) {
      if (forces != nullptr && in->fragment_count >= 0) {
        for (int32_t i = 0; i < in->fragment_count; ++i) forces[i] = {0.0, 0.0, 0.0};
      }
      if (stats != nullptr) *stats = {};
      return s;
    }
    in->pose = {c.eye_m, c.right, c.up, c.forward, c.velocity_mps};
    in->camera_poses = &in->pose;
    in->camera_count = 1;
  }
  return fragsim_controller_step(ctl, in, in != nullptr ? in->fragments : nullptr,
                                 in != nullptr ? in->fragment_count : 0, forces, stats);
}

fragsim_status step_arrays(fragsim_controller_id ctl, TestInput* in,
                           const fragsim_fragment_arrays* arrays, int32_t count,
                           fragsim_step_stats* stats) {
  const WholeCamera& c = in->camera;
  const fragsim_camera_def d{c.fovy_deg,    c.aspect,        c.near_m,         c.far_m,
                             c.body_half_m, c.max_speed_mps, c.max_accel_mps2, c.max_turn_degps};
  if (fragsim_controller_set_cameras(ctl, &d, 1) != FRAGSIM_OK) return FRAGSIM_ERROR_INTERNAL;
  in->pose = {c.eye_m, c.right, c.up, c.forward, c.velocity_mps};
  in->camera_poses = &in->pose;
  in->camera_count = 1;
  return fragsim_controller_step_arrays(ctl, in, arrays, count, stats);
}

// A still camera at the origin looking down -z (the default camera), zero gravity unless asked.
TestInput still_input(const std::vector<fragsim_fragment>& fragments) {
  TestInput in;
  static_cast<fragsim_step_input&>(in) = fragsim_default_step_input();
  in.gravity_mps2 = {0.0, 0.0, 0.0};
  in.ground_height_m = -10.0;
  in.camera = default_camera();
  in.fragments = fragments.data();
  in.fragment_count = static_cast<int32_t>(fragments.size());
  return in;
}

fragsim_fragment fragment(double x, double y, double z, double vx, double vy, double vz,
                          std::uint64_t id) {
  fragsim_fragment f{};
  f.position_m = {x, y, z};
  f.velocity_mps = {vx, vy, vz};
  f.radius_m = 0.05;
  f.mass_kg = 2.0;
  f.id = id;
  return f;
}

// The StepContext the library builds for `in` (the horizon cap goes to the strategy's
// parameters; the shot's end, if any, is the context's).
fragsim::StepContext context_for(const TestInput& in, std::vector<fragsim::FragmentState>& states) {
  states.clear();
  for (int32_t i = 0; i < in.fragment_count; ++i) {
    const fragsim_fragment& f = in.fragments[i];
    fragsim::FragmentState s;
    s.position_m = {f.position_m.x, f.position_m.y, f.position_m.z};
    s.velocity_mps = {f.velocity_mps.x, f.velocity_mps.y, f.velocity_mps.z};
    s.radius_m = f.radius_m;
    s.mass_kg = f.mass_kg;
    s.touched = f.touched != 0;
    states.push_back(s);
  }
  auto v = [](const fragsim_vec3& a) { return Eigen::Vector3d(a.x, a.y, a.z); };
  fragsim::StepContext ctx;
  ctx.t_s = in.time_s;
  ctx.dt_s = in.dt_s;
  ctx.end_time_s = in.end_time_s;
  ctx.camera.eye_m = v(in.camera.eye_m);
  ctx.camera.right = v(in.camera.right);
  ctx.camera.up = v(in.camera.up);
  ctx.camera.forward = v(in.camera.forward);
  ctx.camera.fovy_deg = in.camera.fovy_deg;
  ctx.camera.aspect = in.camera.aspect;
  ctx.camera.near_m = in.camera.near_m;
  ctx.camera.far_m = in.camera.far_m;
  ctx.camera_velocity_mps = v(in.camera.velocity_mps);
  ctx.camera_max_speed_mps = in.camera.max_speed_mps;
  ctx.camera_max_accel_mps2 = in.camera.max_accel_mps2;
  ctx.camera_max_turn_degps = in.camera.max_turn_degps;
  ctx.camera_body_half_m = v(in.camera.body_half_m);
  ctx.gravity_mps2 = v(in.gravity_mps2);
  ctx.ground_height_m = in.ground_height_m;
  ctx.fragments = states;
  return ctx;
}

// What a C caller can do and C++ may not (an enum object holding a value outside its range).
template <class E>
void set_raw(E& e, int v) {
  static_assert(sizeof(E) == sizeof(int));
  std::memcpy(&e, &v, sizeof v);
}

std::vector<fragsim_vec3> dense(const fragsim::StepOutput& out, std::size_t n) {
  std::vector<fragsim_vec3> f(n, fragsim_vec3{0.0, 0.0, 0.0});
  for (const fragsim::AppliedForce& a : out.forces) {
    f[static_cast<std::size_t>(a.fragment)] = {a.force_N.x(), a.force_N.y(), a.force_N.z()};
  }
  return f;
}

TEST(Controller, VersionMatchesTheHeader) {
  EXPECT_EQ(fragsim_version(), FRAGSIM_CONTROL_VERSION);
  EXPECT_EQ(std::string(fragsim_version_string()),
            std::to_string(FRAGSIM_CONTROL_VERSION_MAJOR) + "." +
                std::to_string(FRAGSIM_CONTROL_VERSION_MINOR) + "." +
                std::to_string(FRAGSIM_CONTROL_VERSION_PATCH));
}

TEST(Controller, DefaultsAreTheToolsDefaults) {
  const fragsim_controller_def d = fragsim_default_controller_def();
  const fragsim::EdgeMinParams em;
  const fragsim::EdgeParams e;
  EXPECT_EQ(d.strategy, FRAGSIM_STRATEGY_EDGE_MIN);
  EXPECT_EQ(d.edge_min.margin_m, em.margin_m);
  EXPECT_EQ(d.edge_min.a_max_mps2, em.a_max_mps2);
  EXPECT_EQ(d.edge_min.camera_model, FRAGSIM_CAMERA_BOUNDED_ACCEL);  // the tool's default
  EXPECT_EQ(d.edge_min.camera_accel_mps2, em.camera_accel_mps2);
  EXPECT_EQ(d.edge_min.camera_turn_degps, em.camera_turn_degps);
  for (std::size_t k = 0; k < 4; ++k) EXPECT_EQ(d.edge_min.edge_weights[k], em.edge_weights[k]);
  EXPECT_EQ(d.edge_min.cover_max, 1.0);  // off
  EXPECT_EQ(d.edge_min.cover_region, em.cover_region);
  EXPECT_EQ(d.edge.k_Nms2, e.k);
  EXPECT_EQ(d.edge.replan, FRAGSIM_EDGE_REPLAN_NEVER);
  EXPECT_EQ(d.deflect_all.accel_mps2, 60.0);
  EXPECT_EQ(d.horizon_cap_s, 3.0);
}

// The default camera's frustum is the tool's (geometry/frustum.hpp), and what control.h says it is.
TEST(Controller, DefaultCameraHasTheToolsDefaultFrustum) {
  const fragsim_camera_def c = fragsim_default_camera_def();
  EXPECT_EQ((fragsim::FrustumDef{c.fovy_deg, c.aspect, c.near_m, c.far_m}),
            fragsim::kDefaultFrustum);
  EXPECT_EQ((fragsim::FrustumDef{c.fovy_deg, c.aspect, c.near_m, c.far_m}),
            (fragsim::FrustumDef{60.0, 16.0 / 9.0, 0.1, 500.0}));
}

TEST(Controller, DefThatSkippedTheDefaultsFunctionIsRefused) {
  for (unsigned char fill : {0x00, 0xab}) {
    fragsim_controller_def def;
    std::memset(&def, fill, sizeof def);
    fragsim_controller_id ctl{123, 456};  // must become the null id
    char message[128] = "unchanged";
    EXPECT_EQ(fragsim_controller_create(&def, &ctl, message, sizeof message),
              FRAGSIM_ERROR_DEF_NOT_DEFAULTED);
    EXPECT_TRUE(fragsim_controller_id_is_null(ctl));
    EXPECT_NE(std::string(message).find("fragsim_default_controller_def"), std::string::npos);
  }
}

TEST(Controller, BadDefValuesAreRefusedNamingTheField) {
  struct Case {
    void (*change)(fragsim_controller_def&);
    const char* field;
  };
  const Case cases[] = {
      {[](fragsim_controller_def& d) { d.edge_min.a_max_mps2 = kNaN; }, "edge_min.a_max_mps2"},
      {[](fragsim_controller_def& d) { d.edge_min.margin_m = -0.01; }, "edge_min.margin_m"},
      // The scene file's range for the same parameter (edge-min.a_max_mps2 is at most 1e9).
      {[](fragsim_controller_def& d) { d.edge_min.a_max_mps2 = 2e9; }, "edge_min.a_max_mps2"},
      {[](fragsim_controller_def& d) { d.edge_min.max_solves = -1; }, "edge_min.max_solves"},
      {[](fragsim_controller_def& d) {
         for (double& w : d.edge_min.edge_weights) w = 0.0;
       },
       "edge_min.edge_weights"},
      {[](fragsim_controller_def& d) { d.edge_min.edge_weights[2] = -1.0; },
       "edge_min.edge_weights"},
      {[](fragsim_controller_def& d) { d.edge_min.cover_max = -0.1; }, "edge_min.cover_max"},
      {[](fragsim_controller_def& d) { d.edge_min.cover_region = kNaN; }, "edge_min.cover_region"},
      {[](fragsim_controller_def& d) { set_raw(d.edge_min.camera_model, 9); },
       "edge_min.camera_model"},
      {[](fragsim_controller_def& d) { d.horizon_cap_s = 0.0; }, "horizon_cap_s"},
      {[](fragsim_controller_def& d) { d.horizon_cap_s = kInf; }, "horizon_cap_s"},
      {[](fragsim_controller_def& d) { set_raw(d.strategy, 7); }, "strategy"},
      {[](fragsim_controller_def& d) {
         d.strategy = FRAGSIM_STRATEGY_EDGE;
         d.edge.k_Nms2 = -1.0;
       },
       "edge.k_Nms2"},
      {[](fragsim_controller_def& d) {
         d.strategy = FRAGSIM_STRATEGY_DEFLECT_ALL;
         d.deflect_all.range_m = kInf;
       },
       "deflect_all.range_m"},
  };
  for (const Case& c : cases) {
    fragsim_controller_def def = fragsim_default_controller_def();
    c.change(def);
    fragsim_controller_id ctl{};
    char message[128];
    EXPECT_EQ(fragsim_controller_create(&def, &ctl, message, sizeof message),
              FRAGSIM_ERROR_INVALID_ARGUMENT)
        << c.field;
    EXPECT_TRUE(fragsim_controller_id_is_null(ctl));
    EXPECT_EQ(std::string(message).rfind(c.field, 0), 0u) << message;
  }
  // A message buffer too small is cut, still NUL-terminated.
  fragsim_controller_def def = fragsim_default_controller_def();
  def.horizon_cap_s = -1.0;
  fragsim_controller_id ctl{};
  char tiny[6] = "xxxxx";
  EXPECT_EQ(fragsim_controller_create(&def, &ctl, tiny, sizeof tiny),
            FRAGSIM_ERROR_INVALID_ARGUMENT);
  EXPECT_STREQ(tiny, "horiz");
}

TEST(Controller, NullArgumentsGiveAStatusNotACrash) {
  fragsim_controller_id ctl{};
  EXPECT_EQ(fragsim_controller_create(nullptr, &ctl, nullptr, 0), FRAGSIM_ERROR_NULL_ARGUMENT);
  const fragsim_controller_def def = fragsim_default_controller_def();
  EXPECT_EQ(fragsim_controller_create(&def, nullptr, nullptr, 0), FRAGSIM_ERROR_NULL_ARGUMENT);
  Controller c(def);
  const std::vector<fragsim_fragment> frags{fragment(0, 0, -5, 0, 0, 10, 1)};
  TestInput in = still_input(frags);
  std::vector<fragsim_vec3> forces(1, fragsim_vec3{7, 7, 7});
  EXPECT_EQ(step_with(fragsim_controller_id{}, &in, forces.data(), nullptr),
            FRAGSIM_ERROR_STALE_ID);
  EXPECT_EQ(forces[0].x, 0.0);  // zeroed: the input was readable
  EXPECT_EQ(step_with(c.ctl, nullptr, forces.data(), nullptr), FRAGSIM_ERROR_NULL_ARGUMENT);
  EXPECT_EQ(step_with(c.ctl, &in, nullptr, nullptr), FRAGSIM_ERROR_NULL_ARGUMENT);
  EXPECT_NE(std::string(fragsim_controller_last_error(c.ctl)).find("forces_N"), std::string::npos);
  in.fragments = nullptr;
  EXPECT_EQ(step_with(c.ctl, &in, forces.data(), nullptr), FRAGSIM_ERROR_NULL_ARGUMENT);
  in.fragment_count = 0;  // no fragments: NULL arrays are fine
  EXPECT_EQ(step_with(c.ctl, &in, nullptr, nullptr), FRAGSIM_OK);
  EXPECT_STREQ(fragsim_controller_last_error(c.ctl), "");
  EXPECT_NE(std::string(fragsim_controller_last_error(fragsim_controller_id{})).find("null id"),
            std::string::npos);
  EXPECT_EQ(fragsim_controller_destroy(fragsim_controller_id{}), FRAGSIM_OK);
}

// Hand computation (edge_min_strategy.hpp): zero gravity, a still camera; the protected box is
// half height max(0.1 tan 30 deg, 0.1) + 0.05 = 0.15 m, half width max(0.1026, 0.15) + 0.05 =
// 0.2 m, front max(0.1, 0.15) + 0.05 = 0.2 m. A fragment (radius 0.05 m, mass 2 kg) 5 m ahead,
// 2 cm above the axis, coming at 10 m/s, enters the grown box at t = (5 - 0.25) / 10 = 0.475 s;
// the cheapest way out is up, by 0.15 + 0.05 - 0.02 = 0.18 m, which a constant acceleration a
// covers in (t^2 + t dt) / 2: a = 0.18 / (0.5 (0.475^2 + 0.475 / 60)) = 1.541480 m/s^2.
TEST(Controller, FragmentFiredAtAStillCameraGetsTheEdgeMinForce) {
  const fragsim_controller_def def = fragsim_default_controller_def();
  Controller c(def);
  const std::vector<fragsim_fragment> frags{fragment(0.0, 0.02, -5.0, 0.0, 0.0, 10.0, 42)};
  TestInput in = still_input(frags);
  std::vector<fragsim_vec3> forces(1);
  fragsim_step_stats stats{};
  ASSERT_EQ(step_with(c.ctl, &in, forces.data(), &stats), FRAGSIM_OK);
  const double t = 0.475;
  const double a = 0.18 / (0.5 * (t * t + t * kDt));
  EXPECT_NEAR(forces[0].y, 2.0 * a, 1e-9 * 2.0 * a);
  EXPECT_EQ(forces[0].x, 0.0);
  EXPECT_EQ(forces[0].z, 0.0);
  EXPECT_EQ(stats.candidates, 1);
  EXPECT_EQ(stats.pushed, 1);
  EXPECT_EQ(stats.capped, 0);
  EXPECT_EQ(stats.new_ids, 1);
  EXPECT_EQ(stats.rejected_cheaply, 0);  // a threat: only the exact solve settles it

  // The same as the tool's EdgeMinStrategy given the same context, to the bit.
  std::vector<fragsim::FragmentState> states;
  fragsim::EdgeMinStrategy strategy{fragsim::EdgeMinParams{}};
  fragsim::StepOutput out;
  strategy.step(context_for(in, states), out);
  const std::vector<fragsim_vec3> tool = dense(out, 1);
  EXPECT_EQ(std::memcmp(&tool[0], &forces[0], sizeof(fragsim_vec3)), 0);
}

// The same fragment with the top forbidden (edge_weights 0 1 1 1): the next cheapest way out is
// down, by 0.15 + 0.05 + 0.02 = 0.22 m (sideways would be 0.2 + 0.05 = 0.25 m), so
// a = 0.22 / (0.5 (0.475^2 + 0.475 / 60)), pointing down; the tool's strategy with the same
// weights gives the same bits.
TEST(Controller, ForbiddenTopEdgeSendsTheFragmentDown) {
  fragsim_controller_def def = fragsim_default_controller_def();
  def.edge_min.edge_weights[0] = 0.0;
  Controller c(def);
  const std::vector<fragsim_fragment> frags{fragment(0.0, 0.02, -5.0, 0.0, 0.0, 10.0, 42)};
  TestInput in = still_input(frags);
  std::vector<fragsim_vec3> forces(1);
  ASSERT_EQ(step_with(c.ctl, &in, forces.data(), nullptr), FRAGSIM_OK);
  const double t = 0.475;
  const double a = 0.22 / (0.5 * (t * t + t * kDt));
  EXPECT_NEAR(forces[0].y, -2.0 * a, 1e-9 * 2.0 * a);
  EXPECT_EQ(forces[0].x, 0.0);
  EXPECT_EQ(forces[0].z, 0.0);

  std::vector<fragsim::FragmentState> states;
  fragsim::EdgeMinParams params;
  params.edge_weights = {0.0, 1.0, 1.0, 1.0};
  fragsim::EdgeMinStrategy strategy{params};
  fragsim::StepOutput out;
  strategy.step(context_for(in, states), out);
  const std::vector<fragsim_vec3> tool = dense(out, 1);
  EXPECT_EQ(std::memcmp(&tool[0], &forces[0], sizeof(fragsim_vec3)), 0);
}

// A wall of 64 fragments 6 m ahead (an 8 x 8 grid 0.5 m apart, radius 0.3 m: discs that overlap
// into a 4.1 m square) coming at 9 m/s. The central region at 6 m is half the screen's height and
// width: 2 * 6 tan 30 deg / 2 = 3.46 m by 3.46 * 16/9 = 6.16 m, of which the wall covers
// 4.1 x 3.46 m, 67%, and more as it nears. With cover_max = 0.3 fragments beyond the ones
// threatening the camera are pushed out of the region; the tool's strategy gives the same bits.
TEST(Controller, CoverMaxPushesTheWallOutOfTheCentre) {
  std::vector<fragsim_fragment> frags;
  for (int i = 0; i < 64; ++i) {
    fragsim_fragment f = fragment(0.5 * (i % 8) - 1.75, 0.5 * (i / 8) - 1.75, -6.0, 0.0, 0.0, 9.0,
                                  500 + static_cast<std::uint64_t>(i));
    f.radius_m = 0.3;
    frags.push_back(f);
  }
  TestInput in = still_input(frags);
  int pushed[2] = {0, 0};
  for (int bounded = 0; bounded < 2; ++bounded) {
    fragsim_controller_def def = fragsim_default_controller_def();
    if (bounded) def.edge_min.cover_max = 0.3;
    Controller c(def);
    std::vector<fragsim_vec3> forces(frags.size());
    fragsim_step_stats stats{};
    ASSERT_EQ(step_with(c.ctl, &in, forces.data(), &stats), FRAGSIM_OK);
    pushed[bounded] = stats.pushed;

    std::vector<fragsim::FragmentState> states;
    fragsim::EdgeMinParams params;
    params.cover_max = def.edge_min.cover_max;
    fragsim::EdgeMinStrategy strategy{params};
    strategy.reset(static_cast<int>(frags.size()));
    fragsim::StepOutput out;
    strategy.step(context_for(in, states), out);
    const std::vector<fragsim_vec3> tool = dense(out, frags.size());
    EXPECT_EQ(std::memcmp(tool.data(), forces.data(), forces.size() * sizeof forces[0]), 0)
        << "cover_max " << def.edge_min.cover_max;
  }
  EXPECT_GT(pushed[0], 0);  // the fragments on course for the camera
  EXPECT_GT(pushed[1], pushed[0]) << "the bound must push more than the camera alone";
}

// Fragments 20 m behind a still camera (+z; it looks down -z), flying away at 1 m/s with no
// gravity, are within 20 + 3 m of the eye at most over the 3 s look-ahead and never nearer than
// 20 m: far outside the protected box (its farthest corner 0.32 m away) and the grown one, so
// the cheap rejection settles every one. A fifth fired at the lens (the case above) is not.
TEST(Controller, StatsCountTheFragmentsRejectedCheaply) {
  std::vector<fragsim_fragment> frags;
  for (int i = 0; i < 4; ++i) frags.push_back(fragment(0.3 * i, 0.0, 20.0, 0.0, 0.0, 1.0, 10 + i));
  for (const fragsim_camera_model model : {FRAGSIM_CAMERA_CONSTANT, FRAGSIM_CAMERA_BOUNDED_ACCEL}) {
    fragsim_controller_def def = fragsim_default_controller_def();
    def.edge_min.camera_model = model;
    Controller c(def);
    std::vector<fragsim_fragment> all = frags;
    TestInput in = still_input(all);
    std::vector<fragsim_vec3> forces(all.size());
    fragsim_step_stats stats{};
    ASSERT_EQ(step_with(c.ctl, &in, forces.data(), &stats), FRAGSIM_OK);
    EXPECT_EQ(stats.rejected_cheaply, 4);
    EXPECT_EQ(stats.candidates, 0);
    EXPECT_EQ(stats.pushed, 0);

    all.push_back(fragment(0.0, 0.02, -5.0, 0.0, 0.0, 10.0, 42));
    in = still_input(all);
    forces.resize(all.size());
    ASSERT_EQ(step_with(c.ctl, &in, forces.data(), &stats), FRAGSIM_OK);
    EXPECT_EQ(stats.rejected_cheaply, 4);
    EXPECT_EQ(stats.candidates, 1);
  }
}

TEST(Controller, EveryStrategyMatchesTheToolUnderGravityAndAMovingCamera) {
  std::vector<fragsim_fragment> frags;
  for (int i = 0; i < 64; ++i) {
    const double s = 0.1 * (i % 8) - 0.35;
    const double u = 0.1 * (i / 8) - 0.35;
    frags.push_back(fragment(s, 1.6 + u, -6.0 - 0.05 * i, -0.3 * s, 2.0 - u, 9.0 + 0.1 * i,
                             1000 + static_cast<std::uint64_t>(i)));
  }
  TestInput in = still_input(frags);
  in.gravity_mps2 = {0.0, -9.81, 0.0};
  in.ground_height_m = 0.0;
  in.time_s = 0.25;
  in.camera.eye_m = {0.0, 1.6, -0.5};
  in.camera.velocity_mps = {0.0, 0.0, -2.0};
  for (fragsim_strategy which :
       {FRAGSIM_STRATEGY_EDGE_MIN, FRAGSIM_STRATEGY_EDGE, FRAGSIM_STRATEGY_DEFLECT_ALL}) {
    fragsim_controller_def def = fragsim_default_controller_def();
    def.strategy = which;
    Controller c(def);
    std::vector<fragsim::FragmentState> states;
    std::unique_ptr<fragsim::Strategy> tool;
    if (which == FRAGSIM_STRATEGY_EDGE_MIN) {
      tool = std::make_unique<fragsim::EdgeMinStrategy>(fragsim::EdgeMinParams{});
    } else if (which == FRAGSIM_STRATEGY_EDGE) {
      tool = std::make_unique<fragsim::EdgeStrategy>(fragsim::EdgeParams{});
    } else {
      tool = std::make_unique<fragsim::DeflectAllStrategy>(fragsim::DeflectAllParams{});
    }
    tool->reset(static_cast<int>(frags.size()));
    int pushed = 0;
    for (int step = 0; step < 3; ++step) {  // edge's candidate set carries over
      std::vector<fragsim_vec3> forces(frags.size());
      ASSERT_EQ(step_with(c.ctl, &in, forces.data(), nullptr), FRAGSIM_OK);
      fragsim::StepOutput out;
      tool->step(context_for(in, states), out);
      const std::vector<fragsim_vec3> expected = dense(out, frags.size());
      EXPECT_EQ(std::memcmp(expected.data(), forces.data(), forces.size() * sizeof forces[0]), 0)
          << "strategy " << which << " step " << step;
      pushed += static_cast<int>(out.forces.size());
      for (fragsim_fragment& f : frags) {
        f.position_m.z += f.velocity_mps.z * kDt;
        f.velocity_mps.y -= 9.81 * kDt;
      }
      in.time_s += kDt;
    }
    EXPECT_GT(pushed, 0) << "strategy " << which << ": the scenario must push something";
  }
}

TEST(Controller, NonFiniteOrNegativeInputsAreRefusedWithZeroForces) {
  struct Case {
    void (*change)(TestInput&, std::vector<fragsim_fragment>&);
    fragsim_status status;
    const char* message_start;
  };
  const Case cases[] = {
      {[](TestInput&, std::vector<fragsim_fragment>& f) { f[1].id = f[0].id; },
       FRAGSIM_ERROR_DUPLICATE_ID, "fragments[1].id = 7: the id of fragments[0] too"},
      {[](TestInput& in, std::vector<fragsim_fragment>&) { in.dt_s = 0.0; },
       FRAGSIM_ERROR_INVALID_ARGUMENT, "dt_s = 0"},
      {[](TestInput& in, std::vector<fragsim_fragment>&) { in.dt_s = -kDt; },
       FRAGSIM_ERROR_INVALID_ARGUMENT, "dt_s"},
      {[](TestInput& in, std::vector<fragsim_fragment>&) { in.gravity_mps2.y = kNaN; },
       FRAGSIM_ERROR_INVALID_ARGUMENT, "gravity_mps2.y"},
      {[](TestInput& in, std::vector<fragsim_fragment>&) {
         in.camera.up = {0, 1, 0.1};
       },
       FRAGSIM_ERROR_INVALID_ARGUMENT, "camera_poses[0].up has length"},
      {[](TestInput& in, std::vector<fragsim_fragment>&) { in.camera.max_accel_mps2 = kNaN; },
       FRAGSIM_ERROR_INVALID_ARGUMENT, "cameras[0].max_accel_mps2"},
      {[](TestInput& in, std::vector<fragsim_fragment>&) { in.camera.far_m = 0.05; },
       FRAGSIM_ERROR_INVALID_ARGUMENT, "cameras[0].far_m"},
      {[](TestInput& in, std::vector<fragsim_fragment>&) { in.camera.body_half_m.x = -0.1; },
       FRAGSIM_ERROR_INVALID_ARGUMENT, "cameras[0].body_half_m.x"},
      {[](TestInput& in, std::vector<fragsim_fragment>&) { in.fragment_count = -1; },
       FRAGSIM_ERROR_INVALID_ARGUMENT, "fragment_count = -1"},
  };
  for (fragsim_strategy which : {FRAGSIM_STRATEGY_EDGE_MIN, FRAGSIM_STRATEGY_EDGE}) {
    fragsim_controller_def def = fragsim_default_controller_def();
    def.strategy = which;
    Controller c(def);
    for (const Case& k : cases) {
      std::vector<fragsim_fragment> frags{fragment(0.0, 0.02, -5.0, 0.0, 0.0, 10.0, 7),
                                          fragment(0.1, 0.0, -4.0, 0.0, 0.0, 10.0, 8)};
      TestInput in = still_input(frags);
      k.change(in, frags);
      std::vector<fragsim_vec3> forces(2, fragsim_vec3{7.0, 7.0, 7.0});
      fragsim_step_stats stats{};
      stats.pushed = 99;
      EXPECT_EQ(step_with(c.ctl, &in, forces.data(), &stats), k.status) << k.message_start;
      const std::string message = fragsim_controller_last_error(c.ctl);
      EXPECT_EQ(message.rfind(k.message_start, 0), 0u) << message;
      EXPECT_EQ(stats.pushed, 0);
      const double expect = in.fragment_count < 0 ? 7.0 : 0.0;  // zeroed when the count is valid
      for (const fragsim_vec3& f : forces) {
        EXPECT_EQ(f.x, expect);
        EXPECT_EQ(f.y, expect);
        EXPECT_EQ(f.z, expect);
      }
    }
    // Undeclared camera bounds (FRAGSIM_UNDECLARED) are valid, and a refused call left no trace:
    // the next good call sees both fragments as new.
    std::vector<fragsim_fragment> frags{fragment(0.0, 0.02, -5.0, 0.0, 0.0, 10.0, 7),
                                        fragment(0.1, 0.0, -4.0, 0.0, 0.0, 10.0, 8)};
    TestInput in = still_input(frags);
    std::vector<fragsim_vec3> forces(2);
    fragsim_step_stats stats{};
    EXPECT_EQ(step_with(c.ctl, &in, forces.data(), &stats), FRAGSIM_OK);
    EXPECT_EQ(stats.new_ids, 2);
    EXPECT_GT(forces[0].y, 0.0);
  }
}

TEST(Controller, ExtremeFiniteInputsNeverGiveANonFiniteForce) {
  const double big = 1e300;
  std::vector<fragsim_fragment> frags{
      fragment(0.0, 0.0, -big, 0.0, 0.0, big, 1), fragment(0.0, 0.0, -0.01, 0.0, 0.0, big, 2),
      fragment(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 3),  // inside the camera, at rest
      fragment(1e-300, 0.0, -1.0, 0.0, 0.0, 1e-300, 4)};
  frags[0].mass_kg = big;
  for (fragsim_strategy which :
       {FRAGSIM_STRATEGY_EDGE_MIN, FRAGSIM_STRATEGY_EDGE, FRAGSIM_STRATEGY_DEFLECT_ALL}) {
    for (double dt : {1e-9, kDt, 10.0}) {
      fragsim_controller_def def = fragsim_default_controller_def();
      def.strategy = which;
      Controller c(def);
      TestInput in = still_input(frags);
      in.dt_s = dt;
      in.gravity_mps2 = {0.0, -9.81, 0.0};
      std::vector<fragsim_vec3> forces(frags.size());
      const fragsim_status s = step_with(c.ctl, &in, forces.data(), nullptr);
      EXPECT_TRUE(s == FRAGSIM_OK || s == FRAGSIM_ERROR_INTERNAL) << s;
      for (const fragsim_vec3& f : forces) {
        EXPECT_TRUE(std::isfinite(f.x) && std::isfinite(f.y) && std::isfinite(f.z));
      }
    }
  }
}

// Without gravity a fragment 40.25 m ahead at 10 m/s reaches the box at t = 4 s: beyond the
// default 3 s look-ahead, inside a 5 s one, and beyond a shot that ends at 2 s.
TEST(Controller, TheHorizonCapDecidesHowFarAheadPathsAreExamined) {
  const std::vector<fragsim_fragment> frags{fragment(0.0, 0.02, -40.25, 0.0, 0.0, 10.0, 1)};
  for (double cap : {3.0, 5.0}) {
    for (double end : {kInf, 2.0}) {
      fragsim_controller_def def = fragsim_default_controller_def();
      def.horizon_cap_s = cap;
      Controller c(def);
      TestInput in = still_input(frags);
      in.end_time_s = end;
      std::vector<fragsim_vec3> forces(1);
      ASSERT_EQ(step_with(c.ctl, &in, forces.data(), nullptr), FRAGSIM_OK);
      const bool seen = cap > 4.0 && end > 4.0;
      EXPECT_EQ(forces[0].y > 0.0, seen) << "cap " << cap << " end " << end;
    }
  }
}

// The thesis examines non-candidates only at the first step; the library keys that by id.
TEST(Controller, EdgeKeepsItsCandidateSetByIdAsFragmentsComeAndGo) {
  fragsim_controller_def def = fragsim_default_controller_def();
  def.strategy = FRAGSIM_STRATEGY_EDGE;
  Controller c(def);
  const fragsim_fragment threat = fragment(0.0, 0.02, -5.0, 0.0, 0.0, 10.0, 1);
  // Zero gravity: t_G is the 3 s look-ahead, the camera's ball 3 m/s x 3 s = 9 m (plus radii).
  // 15 m away and receding, id 2 is no candidate at its first step.
  const fragsim_fragment away = fragment(0.5, 0.0, -15.0, 0.0, 0.0, -10.0, 2);
  fragsim_fragment turned = away;  // the same fragment after a bounce: now at the camera
  turned.velocity_mps.z = 10.0;
  auto step = [&c](const std::vector<fragsim_fragment>& frags, fragsim_step_stats& stats) {
    TestInput in = still_input(frags);
    std::vector<fragsim_vec3> forces(frags.size());
    EXPECT_EQ(step_with(c.ctl, &in, forces.data(), &stats), FRAGSIM_OK)
        << fragsim_controller_last_error(c.ctl);
    return forces;
  };
  fragsim_step_stats st{};
  std::vector<fragsim_vec3> f = step({threat, away}, st);
  EXPECT_EQ(st.candidates, 1);
  EXPECT_EQ(st.new_ids, 2);
  EXPECT_GT(std::abs(f[0].y) + std::abs(f[0].x), 0.0);
  EXPECT_EQ(f[1].x, 0.0);

  f = step({threat, turned}, st);  // id 2 was cleared at its first step: never examined again
  EXPECT_EQ(st.candidates, 1);
  EXPECT_EQ(f[1].x + f[1].y + f[1].z, 0.0);

  f = step({turned, threat}, st);  // reordered: the state follows the id, not the index
  EXPECT_EQ(st.candidates, 1);
  EXPECT_EQ(st.new_ids, 0);
  EXPECT_EQ(f[0].x + f[0].y + f[0].z, 0.0);
  EXPECT_GT(std::abs(f[1].y) + std::abs(f[1].x), 0.0);

  fragsim_fragment fresh = turned;
  fresh.id = 3;
  fresh.position_m.x = -0.5;
  f = step({turned, threat, fresh}, st);  // a new id is examined at its first step
  EXPECT_EQ(st.new_ids, 1);
  EXPECT_EQ(st.candidates, 2);
  EXPECT_GT(std::abs(f[2].y) + std::abs(f[2].x), 0.0);

  f = step({threat, fresh}, st);  // id 2 leaves and is forgotten
  EXPECT_EQ(st.dropped_ids, 1);
  f = step({threat, fresh, turned}, st);  // ... so when it returns it is new, and examined
  EXPECT_EQ(st.new_ids, 1);
  EXPECT_EQ(st.candidates, 3);
  EXPECT_GT(std::abs(f[2].y) + std::abs(f[2].x), 0.0);

  fragsim_controller_reset(c.ctl);  // everything new again
  f = step({threat, fresh, turned}, st);
  EXPECT_EQ(st.new_ids, 3);
}

TEST(Controller, StridedArraysGiveTheSameForcesAsStructs) {
  // The engine's own layout: positions and velocities in one array, the rest apart.
  struct Body {
    double position[3];
    float pad;
    double velocity[3];
  };
  std::vector<fragsim_fragment> frags;
  std::vector<Body> bodies;
  std::vector<double> radius, mass;
  std::vector<std::uint64_t> id;
  for (int i = 0; i < 20; ++i) {
    frags.push_back(fragment(0.04 * i - 0.4, 0.03 * i - 0.3, -3.0 - 0.2 * i, 0.0, 0.1, 8.0, 5 * i));
    const fragsim_fragment& f = frags.back();
    bodies.push_back({{f.position_m.x, f.position_m.y, f.position_m.z},
                      0.0f,
                      {f.velocity_mps.x, f.velocity_mps.y, f.velocity_mps.z}});
    radius.push_back(f.radius_m);
    mass.push_back(f.mass_kg);
    id.push_back(f.id);
  }
  const fragsim_controller_def def = fragsim_default_controller_def();
  Controller a(def);
  Controller b(def);
  TestInput in = still_input(frags);
  std::vector<fragsim_vec3> expected(frags.size());
  fragsim_step_stats sa{}, sb{};
  ASSERT_EQ(step_with(a.ctl, &in, expected.data(), &sa), FRAGSIM_OK);
  std::vector<double> out(4 * frags.size(), -1.0);  // stride of 4 doubles: the 4th untouched
  fragsim_fragment_arrays arrays{};
  arrays.position_m = bodies[0].position;
  arrays.position_stride_bytes = sizeof(Body);
  arrays.velocity_mps = bodies[0].velocity;
  arrays.velocity_stride_bytes = sizeof(Body);
  arrays.radius_m = radius.data();
  arrays.radius_stride_bytes = sizeof(double);
  arrays.mass_kg = mass.data();
  arrays.mass_stride_bytes = sizeof(double);
  arrays.id = id.data();
  arrays.id_stride_bytes = sizeof(std::uint64_t);
  arrays.force_N = out.data();
  arrays.force_stride_bytes = 4 * sizeof(double);
  ASSERT_EQ(step_arrays(b.ctl, &in, &arrays, static_cast<int32_t>(frags.size()), &sb), FRAGSIM_OK);
  EXPECT_GT(sa.pushed, 0);
  EXPECT_EQ(sa.pushed, sb.pushed);
  for (std::size_t i = 0; i < frags.size(); ++i) {
    EXPECT_EQ(out[4 * i + 0], expected[i].x);
    EXPECT_EQ(out[4 * i + 1], expected[i].y);
    EXPECT_EQ(out[4 * i + 2], expected[i].z);
    EXPECT_EQ(out[4 * i + 3], -1.0);
  }
  arrays.id = nullptr;
  EXPECT_EQ(step_arrays(b.ctl, &in, &arrays, 20, nullptr), FRAGSIM_ERROR_NULL_ARGUMENT);
  EXPECT_EQ(out[0], 0.0);
}

TEST(Controller, ControllersAreIndependent) {
  fragsim_controller_def def = fragsim_default_controller_def();
  def.strategy = FRAGSIM_STRATEGY_EDGE;
  Controller a(def);
  Controller b(def);
  const std::vector<fragsim_fragment> frags{fragment(0.0, 0.02, -5.0, 0.0, 0.0, 10.0, 1)};
  TestInput in = still_input(frags);
  std::vector<fragsim_vec3> fa(1), fb(1);
  ASSERT_EQ(step_with(a.ctl, &in, fa.data(), nullptr), FRAGSIM_OK);
  in.fragment_count = -3;  // a refused call on b changes nothing of a
  EXPECT_NE(step_with(b.ctl, &in, fb.data(), nullptr), FRAGSIM_OK);
  EXPECT_STREQ(fragsim_controller_last_error(a.ctl), "");
  in.fragment_count = 1;
  ASSERT_EQ(step_with(b.ctl, &in, fb.data(), nullptr), FRAGSIM_OK);
  EXPECT_EQ(std::memcmp(fa.data(), fb.data(), sizeof(fragsim_vec3)), 0);
}

}  // namespace
