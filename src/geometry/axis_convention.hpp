#pragma once
// The frame a file's numbers are written in, and the map into fragsim's (metres, Y up,
// right-handed, as glTF defines its own). An OBJ file or a CSV track states nothing about its
// frame, and engines and modelling tools each write their own (Unreal uses centimetres, Z up,
// left-handed; Unity metres, Y up, left-handed; Blender metres, Z up, right-handed), so the scene
// says which it is.
//
// The map keeps the X axis. A left-handed file is mirrored in its third axis (z when Y is up, y
// when Z is up); a Z-up file is then turned a quarter turn about X so its +Z becomes +Y and
// its +Y becomes -Z (Blender's own glTF export). Hence, for a point (x, y, z) of the file:
//   up y, right: ( x,  y,  z)      up z, right: ( x,  z, -y)
//   up y, left:  ( x,  y, -z)      up z, left:  ( x,  z,  y)
// Every one of these is exact in floating point (signs and swaps only); positions are also
// multiplied by the unit, which is exact whenever the result is representable.

#include <Eigen/Core>

namespace fragsim {

enum class UpAxis { kY, kZ };
enum class Handedness { kRight, kLeft };

struct AxisConvention {
  double unit_m = 1.0;  // metres per file unit, 0.01 for centimetres
  UpAxis up = UpAxis::kY;
  Handedness handedness = Handedness::kRight;

  bool is_identity() const {
    return unit_m == 1.0 && up == UpAxis::kY && handedness == Handedness::kRight;
  }
};

// A direction (a unit vector, a normal's axis) in the file's frame, in fragsim's (no unit).
Eigen::Vector3d direction_to_fragsim(const AxisConvention& c, const Eigen::Vector3d& v);

// A position in the file's frame and units, in fragsim's frame and metres.
Eigen::Vector3d position_to_fragsim(const AxisConvention& c, const Eigen::Vector3d& p);

}  // namespace fragsim
