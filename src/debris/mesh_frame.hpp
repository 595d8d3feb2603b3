#pragma once
// The units and axes a mesh file's coordinates are in, and their conversion to fragsim's frame:
// metres, Y up, right-handed (glTF's own convention). An OBJ file states none of these: what the
// exporting tool used decides (Unreal: centimetres, Z up, left-handed; Unity: metres, Y up,
// left-handed; Blender: metres, Z up, right-handed). The scene says which (object.mesh_unit_m,
// object.mesh_up, object.mesh_handedness).

#include <Eigen/Core>

namespace fragsim {

enum class MeshUp { kY, kZ };
enum class MeshHandedness { kRight, kLeft };

struct MeshFrame {
  double unit_m = 1.0;  // metres per file unit: 0.01 for centimetres
  MeshUp up = MeshUp::kY;
  MeshHandedness handedness = MeshHandedness::kRight;

  // fragsim's own frame: coordinates are taken as they are, to the bit.
  bool is_identity() const {
    return unit_m == 1.0 && up == MeshUp::kY && handedness == MeshHandedness::kRight;
  }
};

// A point of the file in fragsim's frame. x stays x and the file's up axis becomes y; the third
// axis is then the one that makes the frame right-handed. So a left-handed file's depth axis (z
// when Y is up, y when Z is up) is negated, a mirror, and Z up is turned to Y up as Blender's
// glTF exporter does, (x, y, z) -> (x, z, -y). In all: Y up, right: (x, y, z); Y up, left
// (Unity): (x, y, -z); Z up, right (Blender): (x, z, -y); Z up, left (Unreal): (x, z, y); each
// times unit_m.
Eigen::Vector3d to_fragsim_frame(const MeshFrame& frame, const Eigen::Vector3d& file_point);

}  // namespace fragsim
