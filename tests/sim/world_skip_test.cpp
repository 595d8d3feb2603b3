// Skipping what a scene does not need (simulation.auto_disable, simulation.cull_resting): a
// resting fragment is put to sleep or culled after the expected number of steps and then stays
// exactly where it is; a push, the wall, another fragment or the camera coming near wakes it;
// culling never changes a scene whose fragments all stay in view.

#include <gtest/gtest.h>

#include <vector>

#include "sim/camera_path.hpp"
#include "sim/explosion.hpp"
#include "sim/scene_file.hpp"
#include "sim/world.hpp"

namespace fragsim {
namespace {

constexpr double kDt_s = 1.0 / 60.0;
constexpr double kHalf_m = 0.05;  // fragments here are 0.1 m cubes
constexpr double kMass_kg = 0.5;

// A 0.1 m cube at rest on the ground at (x, z): sunk 0.5 mm, inside ODE's 1 mm contact surface
// layer, so the contact holds it without pushing it out and its speed stays ~0 from step 1.
FragmentSpawn resting_cube(double x_m, double z_m) {
  FragmentSpawn s;
  s.position_m = {x_m, kHalf_m - 0.0005, z_m};
  s.velocity_mps.setZero();
  s.angular_velocity_radps.setZero();
  s.half_extents_m = Eigen::Vector3d::Constant(kHalf_m);
  s.mass_kg = kMass_kg;
  return s;
}

// Ground on, gravity, a still camera at (0, 1.6, 0) looking down -z: a cube at z = -3 is in
// view, one at z = +3 is behind the camera.
Scene skip_scene(bool auto_disable, bool cull) {
  Scene s;
  s.name = "skip";
  s.sim.auto_disable = auto_disable;
  s.sim.cull_resting = cull;
  s.sim.rest_steps = 5;
  s.camera.waypoints_m = {{0.0, 1.6, 0.0}};
  s.camera.look_at_m = {{0.0, 1.6, -10.0}};
  s.camera.speed_mps = 0.0;
  return s;
}

// Places the camera where the scene's path has it at t_s and takes one step.
void step_at(World& world, const CameraPath& path, int k) {
  const double t = k * kDt_s;
  world.set_camera(path.pose_at(t), path.velocity_at(t));
  world.step(kDt_s);
}

Eigen::Vector3d position_of(const World& world, int i) {
  std::vector<FragmentState> s = world.init_states();
  return s[static_cast<std::size_t>(i)].position_m;
}

TEST(WorldSkip, RestingFragmentSleepsAfterRestStepsAndThenStaysExactlyFixed) {
  const Scene scene = skip_scene(true, false);
  const CameraPath path(scene.camera);
  World world(scene, {}, {resting_cube(0.0, -3.0)});
  // ODE checks a body at the start of each step from its speed after the previous one (0 here),
  // counting down rest_steps = 5: idle at steps 1..5, disabled at the start of step 5, so the
  // body moves in steps 1 to 4 only.
  for (int k = 0; k < 4; ++k) step_at(world, path, k);
  EXPECT_EQ(world.activity(0), FragmentActivity::kAwake);
  const Eigen::Vector3d rest = position_of(world, 0);
  EXPECT_NEAR(rest.y(), kHalf_m, 1e-3);
  step_at(world, path, 4);
  EXPECT_EQ(world.activity(0), FragmentActivity::kAsleep);
  EXPECT_EQ(world.awake_count(), 0);
  for (int k = 5; k < 200; ++k) step_at(world, path, k);
  EXPECT_EQ(world.activity(0), FragmentActivity::kAsleep);
  EXPECT_EQ(position_of(world, 0), rest);  // exact: a sleeping body is not integrated
  // It still touches the ground, as far as readers of FragmentState are concerned.
  EXPECT_TRUE(world.init_states()[0].touched);
}

TEST(WorldSkip, PushWakesASleepingFragmentAndMovesItByFOverM) {
  Scene scene = skip_scene(true, false);
  scene.ground.friction = 0.0;  // nothing but the push acts along x
  const CameraPath path(scene.camera);
  World world(scene, {}, {resting_cube(0.0, -3.0)});
  for (int k = 0; k < 10; ++k) step_at(world, path, k);
  ASSERT_EQ(world.activity(0), FragmentActivity::kAsleep);
  const Eigen::Vector3d before = position_of(world, 0);
  const double force_N = 2.0;
  const AppliedForce push{0, {force_N, 0.0, 0.0}};
  world.add_forces({&push, 1});
  EXPECT_EQ(world.activity(0), FragmentActivity::kAwake);
  step_at(world, path, 10);
  // Semi-implicit Euler from rest: v = (F/m) dt, x += v dt. 4 N/kg * (1/60 s)^2 = 1.11 mm.
  const double expected_m = force_N / kMass_kg * kDt_s * kDt_s;
  const Eigen::Vector3d moved = position_of(world, 0) - before;
  EXPECT_NEAR(moved.x(), expected_m, 1e-12);
  EXPECT_NEAR(moved.y(), 0.0, 1e-9);
  EXPECT_NEAR(moved.z(), 0.0, 1e-12);
  EXPECT_NEAR(world.init_states()[0].velocity_mps.x(), force_N / kMass_kg * kDt_s, 1e-12);
}

TEST(WorldSkip, RestingFragmentOutOfViewIsCulledAndStaysExactlyFixed) {
  const Scene scene = skip_scene(false, true);
  const CameraPath path(scene.camera);
  // Fragment 0 behind the camera, fragment 1 in view.
  World world(scene, {}, {resting_cube(0.0, 3.0), resting_cube(0.0, -3.0)});
  // The rest count grows after each step (5 after step 5); culling is decided before a step, so
  // fragment 0 is culled in step 6 and does not move from step 6 on.
  for (int k = 0; k < 5; ++k) step_at(world, path, k);
  EXPECT_EQ(world.activity(0), FragmentActivity::kAwake);
  const Eigen::Vector3d rest = position_of(world, 0);
  step_at(world, path, 5);
  EXPECT_EQ(world.activity(0), FragmentActivity::kCulled);
  EXPECT_EQ(world.activity(1), FragmentActivity::kAwake);  // in view: never culled
  EXPECT_EQ(world.culled_count(), 1);
  EXPECT_EQ(world.awake_count(), 1);
  for (int k = 6; k < 200; ++k) step_at(world, path, k);
  EXPECT_EQ(world.activity(0), FragmentActivity::kCulled);
  EXPECT_EQ(world.activity(1), FragmentActivity::kAwake);
  EXPECT_EQ(position_of(world, 0), rest);
}

// At 3 m depth the view's half width is 3 tan(30 deg) 16/9 = 3.079 m; a plane through the eye at
// that edge has the normal (1, 0, -1.026) / 1.433. The cubes' bounding radius is 0.0866 m.
TEST(WorldSkip, OnlyWhatIsWhollyOutsideTheViewIsCulled) {
  const Scene scene = skip_scene(false, true);
  const CameraPath path(scene.camera);
  // Centres 0.154 m and 0.050 m outside the right edge's plane; one ahead, one far behind.
  World world(scene, {},
              {resting_cube(3.30, -3.0), resting_cube(3.15, -3.0), resting_cube(0.0, -3.0),
               resting_cube(0.0, 30.0)});
  for (int k = 0; k < 20; ++k) step_at(world, path, k);
  EXPECT_EQ(world.activity(0), FragmentActivity::kCulled);
  EXPECT_EQ(world.activity(1), FragmentActivity::kAwake);  // its sphere reaches into the view
  EXPECT_EQ(world.activity(2), FragmentActivity::kAwake);
  EXPECT_EQ(world.activity(3), FragmentActivity::kCulled);
}

TEST(WorldSkip, PushUnculls) {
  Scene scene = skip_scene(false, true);
  scene.ground.friction = 0.0;
  const CameraPath path(scene.camera);
  World world(scene, {}, {resting_cube(0.0, 3.0)});
  for (int k = 0; k < 10; ++k) step_at(world, path, k);
  ASSERT_EQ(world.activity(0), FragmentActivity::kCulled);
  const Eigen::Vector3d before = position_of(world, 0);
  const AppliedForce push{0, {0.0, 0.0, -1.0}};
  world.add_forces({&push, 1});
  EXPECT_EQ(world.activity(0), FragmentActivity::kAwake);
  EXPECT_EQ(world.culled_count(), 0);
  step_at(world, path, 10);
  EXPECT_NEAR((position_of(world, 0) - before).z(), -1.0 / kMass_kg * kDt_s * kDt_s, 1e-12);
}

// The camera backs away from what it looks at, along the ground, into a fragment resting behind
// it: out of view, so it is culled, but the camera coming near wakes it in time for the sensor.
TEST(WorldSkip, CameraDrivingIntoACulledFragmentStillHitsIt) {
  for (const bool auto_disable : {false, true}) {
    for (const bool cull : {false, true}) {
      Scene scene = skip_scene(auto_disable, cull);
      scene.camera.waypoints_m = {{0.0, 0.1, 0.0}, {0.0, 0.1, 6.0}};
      scene.camera.look_at_m = {{0.0, 0.1, -10.0}};
      scene.camera.speed_mps = 1.0;
      scene.camera.max_speed_mps = 1.0;
      const CameraPath path(scene.camera);
      World world(scene, {}, {resting_cube(0.0, 4.0)});
      int hit_step = -1;
      bool was_culled = false;
      for (int k = 0; k < 360 && hit_step < 0; ++k) {
        step_at(world, path, k);
        was_culled = was_culled || world.activity(0) == FragmentActivity::kCulled;
        if (!world.camera_hits().empty()) hit_step = k;
      }
      EXPECT_EQ(was_culled, cull) << "auto_disable " << auto_disable;
      // The body's back face (z + 0.15) reaches the cube's front face (z = 3.95) at z = 3.8 m,
      // t = 3.8 s: step 228.
      EXPECT_NEAR(hit_step, 228, 1) << "auto_disable " << auto_disable << " cull " << cull;
    }
  }
}

// The wall strategy's wall, carried toward a sleeping fragment, wakes and pushes it.
TEST(WorldSkip, WallWakesASleepingFragment) {
  Scene scene = skip_scene(true, false);
  scene.camera.waypoints_m = {{0.0, 0.3, 0.0}, {0.0, 0.3, -6.0}};
  scene.camera.look_at_m = {{0.0, 0.3, -10.0}};
  scene.camera.speed_mps = 1.0;
  WorldNeeds needs;
  needs.camera_wall = CameraWallSpec{0.6, 1.0, 1.0, 0.05, 0.3};
  const CameraPath path(scene.camera);
  World world(scene, needs, {resting_cube(0.0, -3.0)});
  for (int k = 0; k < 60; ++k) step_at(world, path, k);
  ASSERT_EQ(world.activity(0), FragmentActivity::kAsleep);
  const Eigen::Vector3d rest = position_of(world, 0);
  // The wall's front face (0.625 m ahead of the eye) meets the cube's face at z = -2.95 m
  // around t = 2.3 s; by t = 3 s the cube has been pushed along.
  for (int k = 60; k < 180; ++k) step_at(world, path, k);
  EXPECT_LT(position_of(world, 0).z(), rest.z() - 0.3);
}

// A fragment falling onto a sleeping (or culled) one wakes it (fragment collisions on).
TEST(WorldSkip, FragmentContactWakesSleepingAndCulledFragments) {
  for (const bool cull : {false, true}) {
    Scene scene = skip_scene(!cull, cull);
    scene.sim.fragment_collisions = true;
    const CameraPath path(scene.camera);
    FragmentSpawn faller = resting_cube(0.02, 3.0);
    faller.position_m.y() = 2.0;  // lands after ~0.63 s (step 38)
    World world(scene, {}, {resting_cube(0.0, 3.0), faller});
    for (int k = 0; k < 30; ++k) step_at(world, path, k);
    ASSERT_EQ(world.activity(0), cull ? FragmentActivity::kCulled : FragmentActivity::kAsleep);
    const Eigen::Vector3d rest = position_of(world, 0);
    bool woke = false;
    for (int k = 30; k < 60; ++k) {
      step_at(world, path, k);
      woke = woke || world.activity(0) == FragmentActivity::kAwake;
    }
    EXPECT_TRUE(woke) << "cull " << cull;
    EXPECT_NE(position_of(world, 0), rest) << "cull " << cull;
    // The faller came to a stop on top of it, not through it.
    EXPECT_GT(position_of(world, 1).y(), rest.y() + kHalf_m);
  }
}

// A small cube bursting in front of a camera that looks at the spot from above: every fragment
// lands and comes to rest in view. Turned away, the camera sees none of them.
Scene pile_scene(bool cull, bool look_away) {
  Scene s;
  s.name = "pile";
  s.sim.duration_s = 4.0;
  s.sim.cull_resting = cull;
  s.object.centre_m = {0.0, 0.5, 0.0};
  s.object.size_m = 0.4;
  s.object.splits = 4;
  s.explosion.speed_mps = 1.5;
  s.camera.waypoints_m = {{0.0, 8.0, 8.0}};
  s.camera.look_at_m = {look_away ? Eigen::Vector3d(0.0, 8.0, 20.0) : Eigen::Vector3d::Zero()};
  s.camera.speed_mps = 0.0;
  return s;
}

struct PileRun {
  std::vector<std::vector<FragmentState>> steps;
  int culled_at_end = 0;
  int touched_at_end = 0;
};

PileRun run_pile(const Scene& scene) {
  const CameraPath path(scene.camera);
  World world(scene, {}, explode(scene));
  PileRun run;
  std::vector<FragmentState> states = world.init_states();
  for (int k = 0; k < scene.step_count(); ++k) {
    const double t = k * scene.sim.dt_s;
    world.set_camera(path.pose_at(t), path.velocity_at(t));
    world.step(scene.sim.dt_s);
    world.read(states);
    run.steps.push_back(states);
  }
  run.culled_at_end = world.culled_count();
  for (const FragmentState& f : states) run.touched_at_end += f.touched ? 1 : 0;
  return run;
}

TEST(WorldSkip, NeverChangesASceneWhoseFragmentsStayInView) {
  const PileRun plain = run_pile(pile_scene(false, false));
  const PileRun culled = run_pile(pile_scene(true, false));
  EXPECT_EQ(culled.culled_at_end, 0);
  ASSERT_EQ(plain.steps.size(), culled.steps.size());
  for (std::size_t k = 0; k < plain.steps.size(); ++k) {
    for (std::size_t i = 0; i < plain.steps[k].size(); ++i) {
      const FragmentState& a = plain.steps[k][i];
      const FragmentState& b = culled.steps[k][i];
      ASSERT_EQ(a.position_m, b.position_m) << "step " << k << " fragment " << i;
      ASSERT_EQ(a.velocity_mps, b.velocity_mps) << "step " << k << " fragment " << i;
      ASSERT_EQ(a.rotation, b.rotation) << "step " << k << " fragment " << i;
      ASSERT_EQ(a.touched, b.touched) << "step " << k << " fragment " << i;
    }
  }
  // The same fragments do come to rest: with the camera turned away, all 64 are culled.
  const PileRun away = run_pile(pile_scene(true, true));
  EXPECT_EQ(away.culled_at_end, 64);
  EXPECT_EQ(away.touched_at_end, 64);
}

TEST(WorldSkip, ParseRoundTripAndRanges) {
  const Scene s = parse_scene(
      "[simulation]\n"
      "auto_disable = on\n"
      "cull_resting = yes\n"
      "rest_linear_mps = 0.02\n"
      "rest_angular_radps = 0.03\n"
      "rest_steps = 7\n",
      "skip.ini");
  EXPECT_TRUE(s.sim.auto_disable);
  EXPECT_TRUE(s.sim.cull_resting);
  EXPECT_EQ(s.sim.rest_linear_mps, 0.02);
  EXPECT_EQ(s.sim.rest_angular_radps, 0.03);
  EXPECT_EQ(s.sim.rest_steps, 7);
  const Scene back = parse_scene(scene_to_ini(s), "back.ini");
  EXPECT_EQ(scene_to_ini(back), scene_to_ini(s));
  EXPECT_TRUE(back.sim.auto_disable);
  EXPECT_EQ(back.sim.rest_steps, 7);
  // Off by default.
  EXPECT_FALSE(Scene{}.sim.auto_disable);
  EXPECT_FALSE(Scene{}.sim.cull_resting);

  auto error_of = [](const std::string& text) {
    try {
      parse_scene(text, "bad.ini");
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(error_of("[simulation]\nrest_steps = 0\n"),
            "bad.ini:2: simulation.rest_steps = '0': must be a whole number in [1, 1000000]");
  EXPECT_EQ(error_of("[simulation]\nrest_linear_mps = -1\n"),
            "bad.ini:2: simulation.rest_linear_mps = '-1': must be in [0, 1000]");
  EXPECT_EQ(error_of("[simulation]\nauto_disable = maybe\n"),
            "bad.ini:2: simulation.auto_disable = 'maybe': expected on or off");
}

}  // namespace
}  // namespace fragsim
