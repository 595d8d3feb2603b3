#pragma once
// A run baked as an animated glTF 2.0 binary (`run --bake FILE.glb`): one node per piece with the
// piece's real mesh (debris/mesh_file.hpp's body_polyhedron, the meshes `fracture` writes), the
// camera as a perspective camera node, the ground as a plane, and one animation whose translation
// and rotation channels (LINEAR, 32-bit floats, one time accessor shared by every channel) replay
// the poses of each sampled step. fragsim's frame (metres, Y up, right-handed) is glTF's. The
// recorder is an observer; it reads the snapshots and never changes the run.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "control/geometry/camera_pose.hpp"
#include "control/geometry/fragment_state.hpp"
#include "sim/run_observer.hpp"

namespace fragsim {

// fragsim's version, as the bake's extras record it.
const char* fragsim_version();

// The largest bake written unless --bake-max-mb says otherwise (front.ini's 1,728 pieces over its
// 181 steps take about 10 MB).
inline constexpr double kDefaultBakeLimit_MB = 256.0;

// A unit quaternion (x, y, z, w in glTF's order) of the rotation whose columns are `axes`, with
// w >= 0. `axes` need only be orthonormal to rounding (ODE's matrices, a camera's
// right/up/-forward).
std::array<float, 4> quaternion_xyzw(const Eigen::Matrix3d& axes);

// The camera node's rotation. glTF cameras look down their local -Z with +Y up, so the node's
// axes are right, up and -forward (CameraPose::rotation()).
std::array<float, 4> camera_quaternion_xyzw(const CameraPose& camera);

// One mesh, its vertices about the piece's centre of mass in its body axes, triangles
// counter-clockwise from outside.
struct BakeMesh {
  std::vector<Eigen::Vector3f> vertices_m;
  std::vector<std::uint32_t> triangles;  // three indices per triangle
};

// Everything a bake writes, recorded from one run (or built by hand in tests).
struct BakeTrack {
  std::string scene_name;
  std::uint64_t seed = 0;
  std::string strategy;
  double dt_s = 0.0;
  int every = 1;  // steps between samples
  std::vector<BakeMesh> meshes;
  std::vector<int> piece_mesh;  // each piece's mesh (pieces of one shape share it)
  bool ground = false;
  double ground_height_m = 0.0;
  Eigen::Vector2d ground_centre_xz_m = Eigen::Vector2d::Zero();
  double ground_half_m = 100.0;
  // The camera's constants at the first sample (yfov in degrees as the scene gives it).
  double fovy_deg = 60.0, aspect = 1.0, near_m = 0.1, far_m = 100.0;
  // Each sample's time, then per piece (sample-major) translation x y z and rotation x y z w.
  std::vector<float> times_s;
  std::vector<float> piece_translation_m;
  std::vector<float> piece_rotation;
  std::vector<float> camera_translation_m;  // x y z per sample
  std::vector<float> camera_rotation;       // x y z w per sample
  std::vector<double> camera_near_m;        // the near distance in force per sample (near-plane)

  std::size_t piece_count() const { return piece_mesh.size(); }
  std::size_t sample_count() const { return times_s.size(); }
};

// The mesh of a piece of this shape (if null, of the box of these half extents).
BakeMesh bake_mesh(const ConvexShape* shape, const Eigen::Vector3d& half_extents_m);

// Appends a sample of the time, each fragment's pose and the camera's. Each quaternion takes the
// sign nearer the same track's previous one, so LINEAR interpolation turns the short way.
void add_bake_sample(BakeTrack& track, double t_s, std::span<const FragmentState> fragments,
                     const CameraPose& camera);

// The bytes of the .glb file. The same track gives the same bytes. Throws std::runtime_error if
// the track is inconsistent (no sample, a piece without its poses) or the glTF writer fails.
std::string bake_glb(const BakeTrack& track);

// The animation data alone, before the JSON and the meshes, a lower bound of a bake's size known
// before the run, for --bake-max-mb.
std::size_t bake_animation_bytes(int piece_count, int step_count, int every);

// The file a strategy's bake goes to, `path` itself for a single strategy, else `path` with
// ".<strategy>" before its extension (shot.glb -> shot.edge-min.glb).
std::string bake_file_path(const std::string& path, const std::string& strategy, bool several);

// Records every run it observes, sampling steps 0, every, 2 every, ... and always the last, and
// bakes each run's bytes when it ends.
class GltfBakeRecorder final : public RunObserver {
 public:
  explicit GltfBakeRecorder(int every = 1);
  void begin(const RunInfo& info, const StepSnapshot& initial) override;
  void observe(const StepSnapshot& snap) override;
  void end() override;

  struct Baked {
    std::string strategy;
    std::string bytes;
  };
  // The runs baked so far, in the order they ended.
  const std::vector<Baked>& baked() const { return baked_; }

 private:
  int every_;
  int step_count_ = 0;
  BakeTrack track_;
  std::vector<Baked> baked_;
};

}  // namespace fragsim
