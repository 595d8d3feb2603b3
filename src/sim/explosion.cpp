#include "sim/explosion.hpp"

#include "sim/camera_motion.hpp"
#include "sim/random.hpp"
#include "sim/sampled_camera.hpp"

namespace fragsim {
namespace {

// The ballistic velocity that takes a point from `from` to the camera's eye, flying the
// straight-line distance at mean speed `speed_mps`, to where the eye will be when the debris
// arrives (aim = future) or where it is at t = 0 (aim = present). The arrival time is found by
// fixed-point iteration, which converges as the camera is slower than the debris in any sensible
// scene; the iteration count bounds it otherwise.
Eigen::Vector3d aimed_velocity(const Eigen::Vector3d& from, const CameraMotion& camera,
                               ExplosionAim aim, double speed_mps,
                               const Eigen::Vector3d& gravity_mps2) {
  if (speed_mps <= 0.0) return Eigen::Vector3d::Zero();
  auto target_at = [&](double t_s) {
    return aim == ExplosionAim::kFuture ? camera.eye_at(t_s) : camera.eye_at(0.0);
  };
  double flight_s = 0.0;
  for (int i = 0; i < 32; ++i) flight_s = (target_at(flight_s) - from).norm() / speed_mps;
  if (flight_s <= 0.0) return Eigen::Vector3d::Zero();
  const Eigen::Vector3d d = target_at(flight_s) - from;
  return d / flight_s - 0.5 * gravity_mps2 * flight_s;
}

}  // namespace

Eigen::Vector3d object_centre(const Scene& scene) {
  const ObjectDef& obj = scene.object;
  if (obj.distance_m <= 0.0) return obj.centre_m;
  const CameraDef& cam = scene.camera;
  // A replayed track starts wherever its samples put the eye at t = 0.
  const Eigen::Vector3d eye = cam.mode == CameraMode::kTrack && !cam.track_samples.empty()
                                  ? SampledCamera(cam, cam.track_samples).eye_at(0.0)
                                  : cam.waypoints_m.front();
  return eye + obj.distance_m * (obj.centre_m - eye).normalized();
}

DebrisDef debris_def(const Scene& scene) {
  const ObjectDef& obj = scene.object;
  DebrisDef d;
  d.pattern = obj.pattern;
  d.size_m = obj.size_m;
  d.splits = obj.splits;
  d.gap = obj.gap;
  d.pieces = obj.pieces;
  d.cluster = obj.cluster;
  d.blast_offset_m = scene.explosion.offset_m;
  d.mesh_file = obj.mesh_file;
  d.mesh_frame = obj.mesh_frame();
  d.density_kgpm3 = obj.density_kgpm3;
  d.seed = scene.sim.seed;
  return d;
}

std::vector<Piece> scene_pieces(const Scene& scene) {
  if (scene.object.mesh_pieces) return *scene.object.mesh_pieces;
  return make_pieces(debris_def(scene));
}

int Scene::fragment_count() const {
  if (object.mesh_pieces) return static_cast<int>(object.mesh_pieces->size());
  if (object.mesh_file.empty() && object.pattern == DebrisPattern::kVoronoi) return object.pieces;
  return object.splits * object.splits * object.splits;
}

std::vector<FragmentSpawn> explode(const Scene& scene) {
  return explode(scene, *make_camera_motion(scene));
}

std::vector<FragmentSpawn> explode(const Scene& scene, const CameraMotion& camera) {
  const ExplosionDef& ex = scene.explosion;
  const std::vector<Piece> pieces = scene_pieces(scene);
  const Eigen::Vector3d centre_m = object_centre(scene);
  const Eigen::Vector3d blast_m = centre_m + ex.offset_m;
  const Eigen::Vector3d aim_mps =
      aimed_velocity(centre_m, camera, ex.aim, ex.toward_camera_mps, scene.sim.gravity_mps2);

  Random rng(scene.sim.seed);
  std::vector<FragmentSpawn> out;
  out.reserve(pieces.size());
  for (const Piece& piece : pieces) {
    FragmentSpawn f;
    f.position_m = centre_m + piece.centre_m;
    f.half_extents_m = piece.half_extents_m;
    f.mass_kg = piece.mass_kg;
    f.rotation = piece.rotation;
    f.shape = piece.shape;
    Eigen::Vector3d radial = f.position_m - blast_m;
    // A fragment at the blast centre itself gets a random direction.
    radial = radial.norm() > 1e-12 ? radial.normalized() : random_in_unit_ball(rng).normalized();
    const double scale = 1.0 + ex.jitter * rng.uniform(-1.0, 1.0);
    f.velocity_mps = scale * (ex.speed_mps * radial + aim_mps) +
                     ex.jitter * ex.speed_mps * random_in_unit_ball(rng);
    f.angular_velocity_radps = ex.spin_radps * random_in_unit_ball(rng);
    out.push_back(f);
  }
  return out;
}

}  // namespace fragsim
