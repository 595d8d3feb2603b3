// The explosion over the pieces: grid scenes exactly as before pieces existed, Voronoi and mesh
// pieces placed at their centres of mass, the object keys and their errors. A scene's mesh file
// found beside it is in scene_file_mesh_test.cpp.

#include "sim/explosion.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "debris/mesh_file.hpp"
#include "sim/camera_motion.hpp"
#include "sim/random.hpp"
#include "sim/scene_file.hpp"

namespace fragsim {
namespace {

Eigen::Vector3d unit_ball(Random& rng) {
  for (;;) {
    Eigen::Vector3d v(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
    if (v.squaredNorm() <= 1.0) return v;
  }
}

// The explosion as it was before pieces (commit eb05c3a), for an unaimed blast.
std::vector<FragmentSpawn> explode_before_pieces(const Scene& scene) {
  const ObjectDef& obj = scene.object;
  const ExplosionDef& ex = scene.explosion;
  const int n = obj.splits;
  const double cell_m = obj.size_m / n;
  const double half_m = 0.5 * cell_m * (1.0 - obj.gap);
  const double mass_kg = obj.density_kgpm3 * std::pow(2.0 * half_m, 3);
  const Eigen::Vector3d centre_m = object_centre(scene);
  const Eigen::Vector3d blast_m = centre_m + ex.offset_m;
  const Eigen::Vector3d aim_mps = Eigen::Vector3d::Zero();
  Random rng(scene.sim.seed);
  std::vector<FragmentSpawn> out;
  for (int iz = 0; iz < n; ++iz) {
    for (int iy = 0; iy < n; ++iy) {
      for (int ix = 0; ix < n; ++ix) {
        FragmentSpawn f;
        const Eigen::Vector3d local((ix + 0.5) * cell_m - 0.5 * obj.size_m,
                                    (iy + 0.5) * cell_m - 0.5 * obj.size_m,
                                    (iz + 0.5) * cell_m - 0.5 * obj.size_m);
        f.position_m = centre_m + local;
        f.half_extents_m = Eigen::Vector3d::Constant(half_m);
        f.mass_kg = mass_kg;
        Eigen::Vector3d radial = f.position_m - blast_m;
        radial = radial.norm() > 1e-12 ? radial.normalized() : unit_ball(rng).normalized();
        const double scale = 1.0 + ex.jitter * rng.uniform(-1.0, 1.0);
        f.velocity_mps =
            scale * (ex.speed_mps * radial + aim_mps) + ex.jitter * ex.speed_mps * unit_ball(rng);
        f.angular_velocity_radps = ex.spin_radps * unit_ball(rng);
        out.push_back(f);
      }
    }
  }
  return out;
}

TEST(Explosion, GridIsAsBeforePiecesBitForBit) {
  Scene s;
  s.object.splits = 6;
  s.explosion.offset_m = Eigen::Vector3d(0.1, -0.2, 0.05);
  s.sim.seed = 42;
  const auto now = explode(s);
  const auto before = explode_before_pieces(s);
  ASSERT_EQ(now.size(), before.size());
  for (std::size_t i = 0; i < now.size(); ++i) {
    EXPECT_EQ(now[i].position_m, before[i].position_m);
    EXPECT_EQ(now[i].velocity_mps, before[i].velocity_mps);
    EXPECT_EQ(now[i].angular_velocity_radps, before[i].angular_velocity_radps);
    EXPECT_EQ(now[i].half_extents_m, before[i].half_extents_m);
    EXPECT_EQ(now[i].mass_kg, before[i].mass_kg);
    EXPECT_EQ(now[i].shape, nullptr);
  }
}

TEST(Explosion, VoronoiPiecesFlyFromTheirCentresOfMass) {
  const Scene s =
      parse_scene("[object]\npattern = voronoi\npieces = 100\ncluster = 0.3\n", "v.ini");
  EXPECT_EQ(s.fragment_count(), 100);
  const auto spawns = explode(s);
  const auto pieces = scene_pieces(s);
  ASSERT_EQ(spawns.size(), 100u);
  const Eigen::Vector3d centre_m = object_centre(s);
  double mass_kg = 0.0;
  for (std::size_t i = 0; i < spawns.size(); ++i) {
    EXPECT_EQ(spawns[i].position_m, centre_m + pieces[i].centre_m);
    ASSERT_NE(spawns[i].shape, nullptr);
    EXPECT_EQ(spawns[i].shape->vertices_m, pieces[i].shape->vertices_m);
    EXPECT_EQ(spawns[i].half_extents_m, spawns[i].shape->half_extents_m);
    mass_kg += spawns[i].mass_kg;
  }
  // The cube's mass less the gap's share: 600 kg/m^3 * 1.2^3 m^3 * 0.98^3.
  EXPECT_NEAR(mass_kg, 600.0 * std::pow(1.2, 3) * std::pow(0.98, 3), 1e-9);
}

TEST(Explosion, ObjectKeysAreChecked) {
  EXPECT_THROW(parse_scene("[object]\npieces = 0\n", "b.ini"), SceneError);
  EXPECT_THROW(parse_scene("[object]\npieces = 20001\n", "b.ini"), SceneError);
  EXPECT_THROW(parse_scene("[object]\ncluster = 1\n", "b.ini"), SceneError);
  EXPECT_THROW(parse_scene("[object]\npattern = hexagons\n", "b.ini"), SceneError);
  EXPECT_EQ(parse_scene("", "").object.pattern, DebrisPattern::kGrid);
}

}  // namespace
}  // namespace fragsim
