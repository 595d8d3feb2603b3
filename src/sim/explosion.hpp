#pragma once
// Breaks the object into its pieces (debris/debris_def.hpp) and gives each the velocity the blast
// leaves it with.

#include <memory>
#include <vector>

#include "control/geometry/fragment_state.hpp"
#include "debris/debris_def.hpp"
#include "sim/scene.hpp"

namespace fragsim {

class CameraMotion;

struct FragmentSpawn {
  Eigen::Vector3d position_m;
  Eigen::Vector3d velocity_mps;
  Eigen::Vector3d angular_velocity_radps;
  Eigen::Vector3d half_extents_m;  // the box, or with `shape` the box about its centre of mass
  double mass_kg = 0.0;
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // body axes as columns, in world
  std::shared_ptr<const ConvexShape> shape;                // null for a box (geometry/convex_shape)
};

// The object's centre is object.centre_m or, with object.distance_m set, the point that far from
// the camera's start (its first waypoint, or a track's eye at t = 0) on the line through centre_m.
Eigen::Vector3d object_centre(const Scene& scene);

// What the scene's object breaks into, from its object section and the blast's offset, seeded by
// simulation.seed.
DebrisDef debris_def(const Scene& scene);
// The pieces relative to the object's centre, from the mesh file as loaded with the scene, else
// make_pieces(debris_def(scene)).
std::vector<Piece> scene_pieces(const Scene& scene);

// Deterministic for a given scene (seeded by scene.sim.seed). Fragments are in the pieces' order
// (for a grid x fastest, then y, then z), so fragment i is the same piece of the object in every
// run of the scene; each flies from its centre of mass.
// An aimed blast (explosion.toward_camera_mps > 0) is aimed at `camera`; the first form makes the
// scene's own camera motion.
std::vector<FragmentSpawn> explode(const Scene& scene);
std::vector<FragmentSpawn> explode(const Scene& scene, const CameraMotion& camera);

}  // namespace fragsim
