#include "geometry/axis_convention.hpp"

namespace fragsim {
namespace {

// -x without a negative zero, so a file's 0 stays fragsim's 0 and a mirrored track prints and runs
// as the same track written in fragsim's frame.
double negated(double x) {
  return -x + 0.0;
}

}  // namespace

Eigen::Vector3d direction_to_fragsim(const AxisConvention& c, const Eigen::Vector3d& v) {
  // The mirror first, in the file's own third axis; then the quarter turn for a Z-up file.
  Eigen::Vector3d m = v;
  if (c.handedness == Handedness::kLeft) {
    if (c.up == UpAxis::kY) {
      m.z() = negated(m.z());
    } else {
      m.y() = negated(m.y());
    }
  }
  if (c.up == UpAxis::kZ) return {m.x(), m.z(), negated(m.y())};
  return m;
}

Eigen::Vector3d position_to_fragsim(const AxisConvention& c, const Eigen::Vector3d& p) {
  return direction_to_fragsim(c, p * c.unit_m);
}

}  // namespace fragsim
