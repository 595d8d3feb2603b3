// The speculative ground contacts of src/sim/ground_sweep.cpp, through the world: a convex piece
// falling farther than its height in one step lands on the ground instead of passing wholly below
// it (ODE's convex-plane collider sees only a piece that straddles the plane), and a landing that
// does not need them is left alone.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "sim/camera_path.hpp"
#include "sim/world.hpp"
#include "support/convex_shapes.hpp"
#include "support/test_scenes.hpp"

namespace fragsim {
namespace {

constexpr double kG_mps2 = 9.81;

Scene still_scene() {
  Scene s = test::still_camera_scene("sweep");
  s.sim.gravity_mps2 = {0.0, -kG_mps2, 0.0};
  return s;
}

// A cube-shaped convex piece of half edge half_m, its lowest face gap_m above the ground, falling
// straight down at fall_mps.
std::vector<FragmentSpawn> falling_cube(double half_m, double gap_m, double fall_mps,
                                        double mass_kg) {
  FragmentSpawn s;
  s.shape = std::make_shared<const ConvexShape>(test::cube_shape(half_m));
  s.position_m = {0.0, half_m + gap_m, -5.0};
  s.velocity_mps = {0.0, -fall_mps, 0.0};
  s.angular_velocity_radps.setZero();
  s.half_extents_m = s.shape->half_extents_m;
  s.mass_kg = mass_kg;
  return {s};
}

struct Landing {
  double lowest_y_m = 0.0;  // the piece's lowest point after each step
  double velocity_y_mps = 0.0;
  double centre_y_m = 0.0;
  double highest_y_m = 0.0;
};

std::vector<Landing> drop(const Scene& scene, const std::vector<FragmentSpawn>& spawns, double dt_s,
                          int steps) {
  World world(scene, {}, spawns);
  const CameraPath path(scene.camera);
  std::vector<FragmentState> states = world.init_states();
  std::vector<Landing> out;
  for (int k = 0; k < steps; ++k) {
    world.set_camera(path.pose_at(k * dt_s), path.velocity_at(k * dt_s));
    world.step(dt_s);
    world.read(states);
    const FragmentState& f = states[0];
    double lowest = INFINITY;
    double highest = -INFINITY;
    for (const Eigen::Vector3d& v : f.shape->vertices_m) {
      lowest = std::min(lowest, (f.position_m + f.rotation * v).y());
      highest = std::max(highest, (f.position_m + f.rotation * v).y());
    }
    out.push_back({lowest, f.velocity_mps.y(), f.position_m.y(), highest});
  }
  return out;
}

// A 10 cm cube of 0.5 kg 0.1 m above the ground at 30 m/s, dt 1/60 s: free flight would carry it
// 0.5 m in the step, to 0.4 m below the ground with its top 0.3 m below, where nothing would ever
// stop it. The sweep's contact lets its centre approach by the lowest face's gap only,
// -gap / dt = -6 m/s, less what the contact's CFM keeps (world.cpp's share 1e-3 of the 24 m/s
// taken away: 0.024 m/s, 0.4 mm in the step): it ends the step on the plane and rests there.
TEST(GroundSweep, FastPieceEndsTheStepOnTheGroundAndRests) {
  const double dt_s = 1.0 / 60.0;
  const std::vector<Landing> l = drop(still_scene(), falling_cube(0.05, 0.1, 30.0, 0.5), dt_s, 120);
  const double kept_mps = 1e-3 * (30.0 + kG_mps2 * dt_s - 6.0);
  EXPECT_NEAR(l[0].velocity_y_mps, -6.0 - kept_mps, 1e-3);
  EXPECT_NEAR(l[0].lowest_y_m, -kept_mps * dt_s, 2e-5);
  for (const Landing& s : l) EXPECT_GT(s.lowest_y_m, -0.01);
  EXPECT_NEAR(l.back().lowest_y_m, 0.0, 0.002);  // resting, within ODE's 1 mm surface layer
  EXPECT_NEAR(l.back().velocity_y_mps, 0.0, 1e-3);
}

// Heavy and fast at a long step (600 kg, 200 m/s, dt 0.1 s, a 1 m cube 1 m up): the sweep's
// contact keeps 0.1% of the 190 m/s it takes away (0.19 m/s, 1.9 cm in the step), whatever the
// mass, where an absolute CFM would not (1e-5 x 1.1e6 N: 11 m/s).
// The piece bounces (restitution 0.2) and lands again at 2 m/s, a landing of less than half its
// height that is left to ODE (28 cm in); it never gets half its height through, and rests 8.4 mm
// deep: the 1 mm surface layer plus the pieces' ground CFM (an absolute 1e-5, world.cpp) times
// m g / 4 corners times dt / ERP 0.2 = 7.4 mm.
TEST(GroundSweep, HeavyPieceAtALongStepIsStoppedToo) {
  const double dt_s = 0.1;
  const std::vector<Landing> l =
      drop(still_scene(), falling_cube(0.5, 1.0, 200.0, 600.0), dt_s, 100);
  const double kept_mps = 1e-3 * (200.0 + kG_mps2 * dt_s - 10.0);
  EXPECT_NEAR(l[0].velocity_y_mps, -10.0 - kept_mps, 1e-2);
  EXPECT_NEAR(l[0].lowest_y_m, -kept_mps * dt_s, 1e-3);
  for (const Landing& s : l) EXPECT_GT(s.lowest_y_m, -0.5);
  EXPECT_NEAR(l.back().lowest_y_m, -0.001 - 1e-5 * 600.0 * kG_mps2 / 4.0 * dt_s / 0.2, 1e-4);
  EXPECT_NEAR(l.back().velocity_y_mps, 0.0, 1e-4);
}

// The fast cube of the first test spinning at 2,000 rad/s about x (5.3 turns a step):
// the contact sits at the centre of mass, so the spin neither changes it nor is changed by it.
// Contacts at the corners would hold the corners' velocities, spin included, to the gap: corners
// sweeping down at 70 m/s would fling the cube up (the soak's seed 3023).
TEST(GroundSweep, SpinningPieceLandsAsANonSpinningOne) {
  const double dt_s = 1.0 / 60.0;
  std::vector<FragmentSpawn> spawn = falling_cube(0.05, 0.1, 30.0, 0.5);
  spawn[0].angular_velocity_radps = {2000.0, 0.0, 0.0};
  const std::vector<Landing> l = drop(still_scene(), spawn, dt_s, 1);
  const double kept_mps = 1e-3 * (30.0 + kG_mps2 * dt_s - 6.0);
  EXPECT_NEAR(l[0].velocity_y_mps, -6.0 - kept_mps, 1e-3);
}

// A rod (a 20 x 2 x 2 cm box hull of 0.1 kg) tilted 0.5 rad from the horizontal arrives at 8 m/s
// with its lower end 5 mm into the plane, where the step before left it. ODE's collider holds that
// end, but a rod struck at its end keeps most of its centre's speed (it turns about the end
// instead): the step would carry the centre past the plane, and the rod wholly below, out of reach
// of any corner contact (the physics benchmark's random hulls: 3 of 1,000 went through so). The
// sweep's contact lets the centre come down to the plane and no farther (less the CFM's share of
// the speed it takes away, under 0.1 mm), and the rod never gets wholly below.
TEST(GroundSweep, EndLandingKeepsTheCentreAboveTheGround) {
  const double dt_s = 1.0 / 60.0;
  FragmentSpawn s;
  s.shape = std::make_shared<const ConvexShape>(test::box_hull({0.1, 0.01, 0.01}));
  s.rotation = Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  double lowest_offset_m = INFINITY;
  for (const Eigen::Vector3d& v : s.shape->vertices_m) {
    lowest_offset_m = std::min(lowest_offset_m, (s.rotation * v).y());
  }
  s.position_m = {0.0, -lowest_offset_m - 0.005, -5.0};
  s.velocity_mps = {0.0, -8.0, 0.0};
  s.angular_velocity_radps.setZero();
  s.half_extents_m = s.shape->half_extents_m;
  s.mass_kg = 0.1;
  const double centre_gap_m = s.position_m.y();
  ASSERT_LT(centre_gap_m, (8.0 + kG_mps2 * dt_s) * dt_s);  // free flight would cross the plane
  const std::vector<Landing> l = drop(still_scene(), {s}, dt_s, 120);
  EXPECT_GT(l[0].centre_y_m, -1e-4);
  for (const Landing& f : l) {
    EXPECT_GT(f.highest_y_m, 0.0);
    EXPECT_GT(f.centre_y_m, -1e-4);
  }
  EXPECT_NEAR(l.back().lowest_y_m, 0.0, 0.002);  // resting on the ground
  EXPECT_NEAR(l.back().velocity_y_mps, 0.0, 1e-3);
}

// 1 cm above the ground at 1 m/s: the step carries it 1.9 cm, into the plane by less than half its
// height, so it gets no sweep and ODE's collider does not see it yet: the first step is free
// flight, exactly (semi-implicit Euler: v - g dt, then y + v dt).
TEST(GroundSweep, ShallowLandingIsLeftToTheCollider) {
  const double dt_s = 1.0 / 60.0;
  const std::vector<Landing> l = drop(still_scene(), falling_cube(0.05, 0.01, 1.0, 0.5), dt_s, 60);
  const double v1_mps = -1.0 - kG_mps2 * dt_s;
  EXPECT_NEAR(l[0].velocity_y_mps, v1_mps, 1e-12);
  EXPECT_NEAR(l[0].lowest_y_m, 0.01 + v1_mps * dt_s, 1e-12);
  EXPECT_NEAR(l.back().lowest_y_m, 0.0, 0.002);
}

// The ground off: nothing to sweep against, the piece falls freely through y = 0.
TEST(GroundSweep, NoGroundNoContacts) {
  Scene scene = still_scene();
  scene.ground.enabled = false;
  const double dt_s = 1.0 / 60.0;
  const std::vector<Landing> l = drop(scene, falling_cube(0.05, 0.1, 30.0, 0.5), dt_s, 1);
  EXPECT_NEAR(l[0].velocity_y_mps, -30.0 - kG_mps2 * dt_s, 1e-12);
}

}  // namespace
}  // namespace fragsim
