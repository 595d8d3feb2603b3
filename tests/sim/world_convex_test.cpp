// Convex pieces in the physics world (FragmentSpawn::shape): what ODE is handed (mass, inertia,
// pose), which pairs collide and how (ground plane, camera sensor, wall, another piece), and that
// pieces fly exactly as boxes do and rest on their faces, neither sunk nor floating.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "sim/camera_path.hpp"
#include "sim/scene_file.hpp"
#include "sim/scene_strategies.hpp"
#include "sim/simulation.hpp"
#include "sim/world.hpp"
#include "sim/world_probe.hpp"
#include "support/convex_shapes.hpp"
#include "support/test_scenes.hpp"

namespace fragsim {
namespace {

constexpr double kDt_s = 1.0 / 60.0;
constexpr double kMass_kg = 0.5;
// ODE lets contacts sink by its 1 mm surface layer before it pushes back; the bound.
constexpr double kRestTolerance_m = 0.002;

using test::corner_tetrahedron;
using test::cube_shape;
using test::regular_tetrahedron;

// A still camera at (0, 1.6, 0) looking down -z (right +x, up +y), ground at y = 0.
Scene still_scene() {
  return test::still_camera_scene("convex");
}

FragmentSpawn piece(std::shared_ptr<const ConvexShape> shape, const Eigen::Vector3d& position_m,
                    const Eigen::Matrix3d& rotation = Eigen::Matrix3d::Identity()) {
  FragmentSpawn s;
  s.position_m = position_m;
  s.velocity_mps.setZero();
  s.angular_velocity_radps.setZero();
  s.half_extents_m = shape->half_extents_m;
  s.mass_kg = kMass_kg;
  s.rotation = rotation;
  s.shape = std::move(shape);
  return s;
}

FragmentSpawn box(double half_m, const Eigen::Vector3d& position_m) {
  FragmentSpawn s;
  s.position_m = position_m;
  s.velocity_mps.setZero();
  s.angular_velocity_radps.setZero();
  s.half_extents_m = Eigen::Vector3d::Constant(half_m);
  s.mass_kg = kMass_kg;
  return s;
}

std::shared_ptr<const ConvexShape> shared(ConvexShape s) {
  return std::make_shared<const ConvexShape>(std::move(s));
}

void step_at(World& world, const CameraPath& path, int k) {
  const double t = k * kDt_s;
  world.set_camera(path.pose_at(t), path.velocity_at(t));
  world.step(kDt_s);
}

// The lowest point of a fragment's hull in the world.
double lowest_y_m(const FragmentState& s) {
  double lowest = INFINITY;
  for (const Eigen::Vector3d& v : s.shape->vertices_m) {
    lowest = std::min(lowest, (s.position_m + s.rotation * v).y());
  }
  return lowest;
}

Eigen::Matrix3d axis_angle(const Eigen::Vector3d& axis, double angle_rad) {
  return Eigen::AngleAxisd(angle_rad, axis.normalized()).toRotationMatrix();
}

// --- the shapes themselves -------------------------------------------------------------------

// The hand-written closed forms against integrating the faces' tetrahedra: the test shapes are
// what their comments say.
TEST(WorldConvex, ClosedFormsMatchIntegrationOverTheFaces) {
  for (const ConvexShape& s :
       {cube_shape(0.05), regular_tetrahedron(0.04), corner_tetrahedron(0.12, 0.08, 0.1)}) {
    const test::MassProperties m = test::mass_properties(s.vertices_m, s.faces);
    EXPECT_NEAR(m.volume_m3, s.volume_m3, 1e-15);
    EXPECT_LT(m.centroid_m.norm(), 1e-15);
    EXPECT_LT((m.inertia_per_kg_m2 - s.inertia_per_kg_m2).norm(), 1e-15);
    // Outward faces: every vertex on or behind every face's plane.
    for (std::size_t f = 0; f < s.faces.size(); ++f) {
      EXPECT_GT(s.offsets_m[f], 0.0);
      for (const Eigen::Vector3d& v : s.vertices_m) {
        EXPECT_LE(s.normals[f].dot(v), s.offsets_m[f] + 1e-15);
      }
    }
  }
  // The corner tetrahedron's figures by hand (a = 0.12, b = 0.08, c = 0.1): volume 1.6e-4 m^3,
  // I_xx = 3 (b^2 + c^2) / 80 = 6.15e-4, I_xy = ab / 80 = 1.2e-4 m^2.
  const ConvexShape c = corner_tetrahedron(0.12, 0.08, 0.1);
  EXPECT_NEAR(c.volume_m3, 1.6e-4, 1e-18);
  EXPECT_NEAR(c.inertia_per_kg_m2(0, 0), 6.15e-4, 1e-18);
  EXPECT_NEAR(c.inertia_per_kg_m2(0, 1), 1.2e-4, 1e-18);
}

// --- what ODE is handed -----------------------------------------------------------------------

TEST(WorldConvex, MassInertiaAndPoseHandedToOdeAreTheShapes) {
  const auto shape = shared(corner_tetrahedron(0.12, 0.08, 0.1));
  const Eigen::Matrix3d rot = axis_angle({1.0, 2.0, 0.5}, 0.7);
  const Scene scene = still_scene();
  World world(scene, {}, {piece(shape, {0.3, 1.0, -2.0}, rot), box(0.05, {0.0, 1.0, -2.0})});
  ASSERT_TRUE(WorldProbe::is_convex(world, 0));
  EXPECT_FALSE(WorldProbe::is_convex(world, 1));  // boxes stay boxes

  const ProbeMass m = WorldProbe::mass(world, 0);
  EXPECT_EQ(m.mass_kg, kMass_kg);
  EXPECT_EQ(m.centre_m, Eigen::Vector3d::Zero());
  // Exact: the mass times the shape's tensor, as given (off-diagonal terms included).
  EXPECT_EQ(m.inertia_kgm2, Eigen::Matrix3d(kMass_kg * shape->inertia_per_kg_m2));

  const std::vector<FragmentState> states = world.init_states();
  EXPECT_EQ(states[0].shape, shape.get());
  EXPECT_EQ(states[0].half_extents_m, shape->half_extents_m);
  EXPECT_EQ(states[0].radius_m, shape->radius_m);
  EXPECT_EQ(states[0].mass_kg, kMass_kg);
  EXPECT_LT((states[0].rotation - rot).norm(), 1e-15);  // through ODE's quaternion
  EXPECT_EQ(states[1].shape, nullptr);
  EXPECT_EQ(states[1].radius_m, Eigen::Vector3d::Constant(0.05).norm());
}

// --- which pairs collide ------------------------------------------------------------------------

// ODE's own convex-plane collider: every vertex below the plane, depth as sunk, the plane's normal.
TEST(WorldConvex, ConvexAgainstTheGroundPlane) {
  const auto cube = shared(cube_shape(0.05));
  const Scene scene = still_scene();
  World world(scene, {},
              {piece(cube, {0.0, 0.049, -2.0}), piece(cube, {1.0, 0.051, -2.0}),
               piece(shared(regular_tetrahedron(0.04)), {2.0, 0.039, -2.0})});
  const std::vector<ProbeContact> sunk = WorldProbe::contacts(world, 0, ProbeTarget::kGround);
  ASSERT_EQ(sunk.size(), 4u);  // the bottom face's corners
  for (const ProbeContact& c : sunk) {
    EXPECT_NEAR(c.depth_m, 0.001, 1e-12);
    EXPECT_NEAR(c.normal.y(), 1.0, 1e-12);
    EXPECT_NEAR(c.position_m.y(), -0.001, 1e-12);
  }
  EXPECT_TRUE(WorldProbe::contacts(world, 1, ProbeTarget::kGround).empty());
  // The tetrahedron's two lower vertices (y = -a) are an edge 1 mm under the ground.
  const std::vector<ProbeContact> edge = WorldProbe::contacts(world, 2, ProbeTarget::kGround);
  ASSERT_EQ(edge.size(), 2u);
  for (const ProbeContact& c : edge) EXPECT_NEAR(c.depth_m, 0.001, 1e-12);
}

// The soak's seed 1452, its camera made a still path: 27 Voronoi cells of a 1.45 m cube thrown
// from the eye land at dt 0.1 s under the exact solver. With the world's CFM of 1e-10 on their
// ground contacts ODE reported "LCP internal error, s <= 0" 5 times in this run; with
// kConvexGroundCfm it is silent. (One cell passes wholly below the ground within a step here and
// falls on: ODE's convex-plane collider answers only a piece that straddles the plane; README,
// "Soak".)
TEST(WorldConvex, CellsLandingAtALongStepKeepTheExactSolverQuiet) {
  const Scene scene = parse_scene(
      "[simulation]\ndt_s = 0.1\nduration_s = 30\nseed = 1452\nsolver = exact\n"
      "[object]\ncentre_m = 0 1.6 0\nsize_m = 1.446860359922133\ndistance_m = 0\n"
      "density_kgpm3 = 600\npattern = voronoi\npieces = 27\ncluster = 0.2874089960048225\n"
      "[explosion]\nspeed_mps = 0\njitter = 0.24765536344562455\n"
      "spin_radps = 40.72656591052185\ntoward_camera_mps = 14.206186089413414\n"
      "[ground]\nenabled = on\nfriction = 0.8\nrestitution = 0.2\n",
      "seed1452.ini");
  auto none = make_strategy("none", scene);
  const RunTotals totals = simulate(scene, *none);
  EXPECT_EQ(totals.ode_messages, 0);
  EXPECT_EQ(totals.steps, 300);
}

// The sensor is a box: convex-box goes to libccd (detection is all a sensor needs). A regular
// tetrahedron whose bounding box reaches into the camera body while its hull does not is no hit.
TEST(WorldConvex, ConvexAgainstTheCameraSensorBox) {
  const Scene scene = still_scene();  // body 0.3 x 0.2 x 0.3 m about the eye (0, 1.6, 0)
  const CameraPath path(scene.camera);
  const double a = 0.04;
  const auto tet = shared(regular_tetrahedron(a));
  // The body's corner (0.15, 1.7, 0.15) is 0.6 a deep inside the piece's box, from the box's
  // (-a, -a, -a) corner; there, relative to the piece's centre, x + y + z <= -1.2 a < -a: outside
  // the face opposite (a, a, a).
  const Eigen::Vector3d corner(0.15, 1.7, 0.15);
  World world(scene, {},
              {piece(tet, corner + Eigen::Vector3d::Constant(0.4 * a)),
               piece(tet, {0.0, 1.6 + 0.1 + a - 0.001, -0.05}),  // its lowest edge 1 mm in the top
               piece(tet, {0.0, 1.6 + 0.1 + a + 0.001, -0.05})});
  world.set_camera(path.pose_at(0.0), path.velocity_at(0.0));
  EXPECT_TRUE(WorldProbe::contacts(world, 0, ProbeTarget::kCameraSensor).empty());
  const std::vector<ProbeContact> in = WorldProbe::contacts(world, 1, ProbeTarget::kCameraSensor);
  ASSERT_EQ(in.size(), 1u);
  EXPECT_NEAR(in[0].depth_m, 0.001, 1e-6);
  EXPECT_NEAR(in[0].normal.y(), 1.0, 1e-6);
  EXPECT_TRUE(WorldProbe::contacts(world, 2, ProbeTarget::kCameraSensor).empty());
  world.step(kDt_s);
  EXPECT_EQ(world.camera_hits(), std::vector<int>{1});
}

CameraWallSpec test_wall() {
  CameraWallSpec w;
  w.distance_m = 0.6;
  w.width_m = 2.0;
  w.height_m = 1.5;
  w.thickness_m = 0.1;  // its far face at z = -0.65
  w.restitution = 0.3;
  return w;
}

// The wall is a box: libccd's one point per pair, turned into the face's corners (world.cpp,
// convex_manifold). A cube piece 1 mm into the wall's far face: its four near corners, 1 mm deep,
// pushed along -z, away from the camera.
TEST(WorldConvex, ConvexAgainstTheWallBoxGivesTheFaceCorners) {
  const Scene scene = still_scene();
  const CameraPath path(scene.camera);
  WorldNeeds needs;
  needs.camera_wall = test_wall();
  const auto cube = shared(cube_shape(0.05));
  World world(scene, needs,
              {piece(cube, {0.1, 1.5, -0.65 - 0.05 + 0.001}),
               piece(cube, {0.1, 1.5, -0.65 - 0.05 - 0.001})});
  world.set_camera(path.pose_at(0.0), path.velocity_at(0.0));
  const std::vector<ProbeContact> in = WorldProbe::contacts(world, 0, ProbeTarget::kWall);
  ASSERT_EQ(in.size(), 4u);
  for (const ProbeContact& c : in) {
    EXPECT_NEAR(c.depth_m, 0.001, 1e-6);
    EXPECT_NEAR(c.normal.z(), -1.0, 1e-6);
    EXPECT_NEAR(c.position_m.z(), -0.649, 1e-9);
    EXPECT_NEAR(std::abs(c.position_m.x() - 0.1), 0.05, 1e-9);
  }
  EXPECT_TRUE(WorldProbe::contacts(world, 1, ProbeTarget::kWall).empty());
}

// Fragment collisions: convex-convex and convex-box, also through libccd, also with the manifold.
TEST(WorldConvex, ConvexAgainstConvexAndAgainstABoxFragment) {
  Scene scene = still_scene();
  scene.sim.fragment_collisions = true;
  const auto cube = shared(cube_shape(0.05));
  const auto tet = shared(regular_tetrahedron(0.04));
  World world(scene, {},
              {piece(cube, {0.0, 1.0, -2.0}), piece(cube, {0.099, 1.02, -2.01}),
               piece(cube, {0.0, 1.0, -2.101}), box(0.05, {-0.099, 1.0, -2.0}),
               // The tetrahedron's top edge (y = +a) 1 mm into the first cube's bottom face.
               piece(tet, {0.0, 1.0 - 0.05 - 0.04 + 0.001, -2.0}),
               piece(tet, {0.0, 1.0 - 0.05 - 0.04 - 0.001, -2.0})});
  const std::vector<ProbeContact> side = WorldProbe::contacts(world, 0, ProbeTarget::kFragment, 1);
  // 1 mm face to face, offset: the corners of the faces' overlap, 0.08 x 0.09 m.
  ASSERT_EQ(side.size(), 4u);
  for (const ProbeContact& c : side) {
    EXPECT_NEAR(c.depth_m, 0.001, 1e-6);
    EXPECT_NEAR(c.normal.x(), -1.0, 1e-6);  // fragment 0 is pushed toward -x
  }
  EXPECT_TRUE(WorldProbe::contacts(world, 0, ProbeTarget::kFragment, 2).empty());
  const std::vector<ProbeContact> with_box =
      WorldProbe::contacts(world, 0, ProbeTarget::kFragment, 3);
  ASSERT_EQ(with_box.size(), 4u);
  for (const ProbeContact& c : with_box) {
    EXPECT_NEAR(c.depth_m, 0.001, 1e-6);
    EXPECT_NEAR(c.normal.x(), 1.0, 1e-6);
  }
  // The box fragment sees the same pair from its side.
  const std::vector<ProbeContact> from_box =
      WorldProbe::contacts(world, 3, ProbeTarget::kFragment, 0);
  ASSERT_EQ(from_box.size(), 4u);
  EXPECT_NEAR(from_box[0].normal.x(), -1.0, 1e-6);
  const std::vector<ProbeContact> edge = WorldProbe::contacts(world, 4, ProbeTarget::kFragment, 0);
  ASSERT_EQ(edge.size(), 2u);  // the edge's two ends lie inside the cube
  for (const ProbeContact& c : edge) {
    EXPECT_NEAR(c.depth_m, 0.001, 1e-6);
    EXPECT_NEAR(c.normal.y(), -1.0, 1e-6);
  }
  EXPECT_TRUE(WorldProbe::contacts(world, 5, ProbeTarget::kFragment, 0).empty());
}

// --- flight and rest
// ------------------------------------------------------------------------------

// Free flight does not depend on the shape: a convex cube and a box of the same size and mass
// (so the same inertia, 2 h^2 / 3 per kg) thrown with the same spin follow the same path, to
// rounding, until the first contact; then both rest on a face at h.
TEST(WorldConvex, ConvexCubeFliesAndRestsLikeTheBox) {
  const Scene scene = still_scene();
  const CameraPath path(scene.camera);
  const double h = 0.05;
  FragmentSpawn as_box = box(h, {0.0, 1.0, -3.0});
  as_box.velocity_mps = {0.5, 3.0, -1.0};
  as_box.angular_velocity_radps = {4.0, -2.0, 7.0};
  FragmentSpawn as_piece = piece(shared(cube_shape(h)), as_box.position_m);
  as_piece.velocity_mps = as_box.velocity_mps;
  as_piece.angular_velocity_radps = as_box.angular_velocity_radps;
  World box_world(scene, {}, {as_box});
  World piece_world(scene, {}, {as_piece});
  std::vector<FragmentState> b = box_world.init_states();
  std::vector<FragmentState> p = piece_world.init_states();
  int flight_steps = 0;
  for (int k = 0; k < 300; ++k) {
    step_at(box_world, path, k);
    step_at(piece_world, path, k);
    box_world.read(b);
    piece_world.read(p);
    if (b[0].touched || p[0].touched) break;
    ++flight_steps;
    EXPECT_LT((b[0].position_m - p[0].position_m).norm(), 1e-12) << "step " << k;
    EXPECT_LT((b[0].rotation - p[0].rotation).norm(), 1e-12) << "step " << k;
  }
  EXPECT_GT(flight_steps, 30);  // up 0.46 m and down to the ground: about 0.7 s
  for (int k = flight_steps + 1; k < 300; ++k) {
    step_at(box_world, path, k);
    step_at(piece_world, path, k);
  }
  box_world.read(b);
  piece_world.read(p);
  EXPECT_NEAR(p[0].position_m.y(), b[0].position_m.y(), kRestTolerance_m);
  EXPECT_NEAR(p[0].position_m.y(), h, kRestTolerance_m);
  EXPECT_NEAR(lowest_y_m(p[0]), 0.0, kRestTolerance_m);
  EXPECT_LT(p[0].velocity_mps.norm(), 1e-3);
}

// A regular and an irregular tetrahedron dropped tumbling from 0.5 m come to rest on a face: their
// lowest vertex within 2 mm of the ground (ODE holds contacts ~1 mm deep), still.
TEST(WorldConvex, TetrahedraDroppedOnTheGroundRestOnAFace) {
  const Scene scene = still_scene();
  const CameraPath path(scene.camera);
  std::vector<FragmentSpawn> spawns = {
      piece(shared(regular_tetrahedron(0.04)), {0.0, 0.5, -3.0}, axis_angle({1, 2, 3}, 0.9)),
      piece(shared(corner_tetrahedron(0.12, 0.08, 0.1)), {1.0, 0.5, -3.0},
            axis_angle({-2, 1, 1}, 2.1))};
  spawns[0].angular_velocity_radps = {3.0, 1.0, -2.0};
  spawns[1].velocity_mps = {0.3, 0.0, 0.2};
  spawns[1].angular_velocity_radps = {-1.0, 4.0, 2.0};
  World world(scene, {}, spawns);
  std::vector<FragmentState> s = world.init_states();
  for (int k = 0; k < 300; ++k) step_at(world, path, k);  // 5 s
  world.read(s);
  for (const FragmentState& f : s) {
    EXPECT_NEAR(lowest_y_m(f), 0.0, kRestTolerance_m);
    EXPECT_LT(f.velocity_mps.norm(), 1e-3);
    // On a face: three vertices on the ground, the fourth up at the height over that face.
    int down = 0;
    for (const Eigen::Vector3d& v : f.shape->vertices_m) {
      down += (f.position_m + f.rotation * v).y() < kRestTolerance_m ? 1 : 0;
    }
    EXPECT_EQ(down, 3);
  }
  // The regular one stands on a face: its centroid a / sqrt(3) above it (the face offset).
  EXPECT_NEAR(s[0].position_m.y(), 0.04 / std::sqrt(3.0), kRestTolerance_m);
}

// Fragment collisions on: a convex cube dropped on another resting on the ground comes to rest on
// it, face on face (the manifold's corners; libccd's one point alone let it spin on it). With
// fragment collisions ODE's QuickStep solves the stack, which never quite settles: boxes, with
// ODE's own box-box collider, jitter at 2-6 mm/s and creep 3 mm in the same set-up, so the bound
// here is that of a stack of boxes, not of a lone piece.
TEST(WorldConvex, ConvexCubeRestsOnAnother) {
  Scene scene = still_scene();
  scene.sim.fragment_collisions = true;
  const CameraPath path(scene.camera);
  const auto cube = shared(cube_shape(0.05));
  World world(scene, {},
              {piece(cube, {0.0, 0.0495, -3.0}),
               piece(cube, {0.02, 0.25, -3.01}, axis_angle({0, 1, 0}, 0.3))});
  std::vector<FragmentState> s = world.init_states();
  for (int k = 0; k < 300; ++k) step_at(world, path, k);
  world.read(s);
  const Eigen::Vector3d at_5s = s[1].position_m;
  for (int k = 300; k < 600; ++k) step_at(world, path, k);
  world.read(s);
  EXPECT_NEAR(lowest_y_m(s[0]), 0.0, kRestTolerance_m);
  EXPECT_NEAR(lowest_y_m(s[1]), 0.1, 2.0 * kRestTolerance_m);  // two contact layers
  EXPECT_LT((s[1].position_m - at_5s).norm(), kRestTolerance_m);
  EXPECT_LT(s[1].velocity_mps.norm(), 0.01);
}

// Gravity toward the camera and no ground: a convex cube falls onto the wall's far face and
// rests there, 1 mm deep at most, instead of spinning on one contact point.
TEST(WorldConvex, ConvexCubeRestsOnTheWall) {
  Scene scene = still_scene();
  scene.ground.enabled = false;
  scene.sim.gravity_mps2 = {0.0, 0.0, 9.81};
  const CameraPath path(scene.camera);
  WorldNeeds needs;
  needs.camera_wall = test_wall();
  World world(scene, needs,
              {piece(shared(cube_shape(0.05)), {0.1, 1.5, -0.9}, axis_angle({1, 1, 0}, 0.2))});
  std::vector<FragmentState> s = world.init_states();
  for (int k = 0; k < 300; ++k) step_at(world, path, k);
  world.read(s);
  double nearest_z = -INFINITY;
  for (const Eigen::Vector3d& v : s[0].shape->vertices_m) {
    nearest_z = std::max(nearest_z, (s[0].position_m + s[0].rotation * v).z());
  }
  EXPECT_NEAR(nearest_z, -0.65, kRestTolerance_m);
  EXPECT_NEAR(s[0].position_m.z(), -0.7, kRestTolerance_m);
  EXPECT_LT(s[0].velocity_mps.norm(), 1e-3);
}

// A convex piece fired at the lens, as the near-plane tests fire boxes: the sensor records it.
TEST(WorldConvex, PieceTouchingTheCameraBodyIsACameraHit) {
  Scene scene = still_scene();
  scene.ground.enabled = false;
  scene.sim.gravity_mps2.setZero();
  const CameraPath path(scene.camera);
  FragmentSpawn s = piece(shared(corner_tetrahedron(0.12, 0.08, 0.1)), {0.05, 1.62, -3.0},
                          axis_angle({1, 0, 1}, 0.4));
  s.velocity_mps = {0.0, 0.0, 6.0};
  World world(scene, {}, {s});
  int first_hit = -1;
  for (int k = 0; k < 60 && first_hit < 0; ++k) {
    step_at(world, path, k);
    if (!world.camera_hits().empty()) {
      EXPECT_EQ(world.camera_hits(), std::vector<int>{0});
      first_hit = k;
    }
  }
  // The body's far face is at z = -0.15 and the piece reaches less than its radius, 0.095 m, ahead
  // of its centre: it touches with its centre between z = -0.245 and -0.15, which the centre,
  // from -3 m at 0.1 m a step, reaches in step 28 or 29 (contacts are found before each step).
  EXPECT_GE(first_hit, 28);
  EXPECT_LE(first_hit, 29);
}

}  // namespace
}  // namespace fragsim

namespace fragsim {
namespace {

// An octagonal prism (circumradius r, height 2 h) lying on an octagon: 8 corners on the ground.
ConvexShape octagonal_prism(double r_m, double h_m) {
  std::vector<Eigen::Vector3d> v;
  for (double y : {-h_m, h_m}) {
    for (int k = 0; k < 8; ++k) {
      const double a = k * M_PI / 4.0;
      v.emplace_back(r_m * std::cos(a), y, r_m * std::sin(a));
    }
  }
  std::vector<std::vector<int>> faces = {{0, 1, 2, 3, 4, 5, 6, 7}, {15, 14, 13, 12, 11, 10, 9, 8}};
  for (int k = 0; k < 8; ++k) faces.push_back({k, k + 8, (k + 1) % 8 + 8, (k + 1) % 8});
  const double volume_m3 = 2.0 * std::sqrt(2.0) * r_m * r_m * 2.0 * h_m;
  return test::finish_shape(v, faces, volume_m3, Eigen::Matrix3d::Identity() * r_m * r_m / 4.0);
}

// simulation.convex_ground_contacts: 4 by default, 8 keeps all 8 corners; fewer than 8 are spread
// over the footprint. Of 8 corners on a circle of radius r, farthest-point picking from corner 0
// takes corner 4 (2 r away), then 2 and 6: a square of side r sqrt(2), the widest 4 the octagon
// has.
TEST(WorldConvex, ConvexGroundContactsAreSpreadOverTheFootprint) {
  const double r = 0.05;
  const double h = 0.02;
  const auto prism = shared(octagonal_prism(r, h));
  EXPECT_EQ(Scene{}.sim.convex_ground_contacts, 4);
  for (int keep : {8, 4, 2, 1}) {
    Scene scene = still_scene();
    scene.sim.convex_ground_contacts = keep;
    World world(scene, {}, {piece(prism, {0.0, h - 0.001, -2.0})});
    const std::vector<ProbeContact> c = WorldProbe::contacts(world, 0, ProbeTarget::kGround);
    ASSERT_EQ(c.size(), static_cast<std::size_t>(keep)) << keep;
    double closest_m = INFINITY;
    for (std::size_t i = 0; i < c.size(); ++i) {
      EXPECT_NEAR(c[i].depth_m, 0.001, 1e-12);
      EXPECT_NEAR(c[i].normal.y(), 1.0, 1e-12);
      for (std::size_t j = i + 1; j < c.size(); ++j) {
        closest_m = std::min(closest_m, (c[i].position_m - c[j].position_m).norm());
      }
    }
    if (keep == 4) {
      EXPECT_NEAR(closest_m, r * std::sqrt(2.0), 1e-9);
    }
    if (keep == 2) {
      EXPECT_NEAR(closest_m, 2.0 * r, 1e-9);
    }
    // Between neighbouring corners of the octagon: 2 r sin(22.5 degrees).
    if (keep == 8) {
      EXPECT_NEAR(closest_m, 2.0 * r * std::sin(M_PI / 8.0), 1e-9);
    }
  }
  // A box keeps its 4 whatever the setting.
  Scene scene = still_scene();
  scene.sim.convex_ground_contacts = 1;
  World world(scene, {}, {box(0.05, {0.0, 0.049, -2.0})});
  EXPECT_EQ(WorldProbe::contacts(world, 0, ProbeTarget::kGround).size(), 4u);
}

TEST(WorldConvex, ConvexGroundContactsKeyIsRangeChecked) {
  auto error_of = [](const std::string& text) {
    try {
      parse_scene(text, "bad.ini");
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(parse_scene("[simulation]\nconvex_ground_contacts = 4\n", "ok.ini")
                .sim.convex_ground_contacts,
            4);
  EXPECT_EQ(error_of("[simulation]\nconvex_ground_contacts = 0\n"),
            "bad.ini:2: simulation.convex_ground_contacts = '0': must be a whole number in [1, 8]");
  EXPECT_EQ(error_of("[simulation]\nconvex_ground_contacts = 9\n"),
            "bad.ini:2: simulation.convex_ground_contacts = '9': must be a whole number in [1, 8]");
}

}  // namespace
}  // namespace fragsim
