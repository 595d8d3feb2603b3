#include "sim/face_manifold.hpp"

#include <algorithm>
#include <cmath>

namespace fragsim {
namespace {

// A box's corners (bit 0 is +x, bit 1 +y, bit 2 +z) and faces, counter-clockwise from outside, with
// normals +x, -x, +y, -y, +z, -z.
const std::vector<std::vector<int>>& box_faces() {
  static const std::vector<std::vector<int>> faces = {{1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3},
                                                      {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1}};
  return faces;
}

}  // namespace

WorldHull place_hull(const Eigen::Vector3d& position_m, const Eigen::Matrix3d& rotation,
                     const std::vector<Eigen::Vector3d>& vertices_m,
                     const std::vector<std::vector<int>>& faces,
                     const std::vector<Eigen::Vector3d>& normals,
                     const std::vector<double>& offsets_m) {
  WorldHull h;
  h.faces = &faces;
  h.vertices_m.reserve(vertices_m.size());
  for (const Eigen::Vector3d& v : vertices_m) h.vertices_m.push_back(position_m + rotation * v);
  h.normals.reserve(normals.size());
  h.offsets_m.reserve(normals.size());
  for (std::size_t k = 0; k < normals.size(); ++k) {
    const Eigen::Vector3d n = rotation * normals[k];
    h.normals.push_back(n);
    h.offsets_m.push_back(offsets_m[k] + n.dot(position_m));
  }
  return h;
}

WorldHull place_box(const Eigen::Vector3d& position_m, const Eigen::Matrix3d& rotation,
                    const Eigen::Vector3d& half_m) {
  std::vector<Eigen::Vector3d> vertices;
  for (int i = 0; i < 8; ++i) {
    vertices.emplace_back((i & 1) ? half_m.x() : -half_m.x(), (i & 2) ? half_m.y() : -half_m.y(),
                          (i & 4) ? half_m.z() : -half_m.z());
  }
  std::vector<Eigen::Vector3d> normals;
  std::vector<double> offsets;
  for (int a = 0; a < 3; ++a) {
    for (double sign : {1.0, -1.0}) {
      normals.push_back(sign * Eigen::Vector3d::Unit(a));
      offsets.push_back(half_m[a]);
    }
  }
  return place_hull(position_m, rotation, vertices, box_faces(), normals, offsets);
}

FaceManifold face_manifold(const WorldHull& a, const WorldHull& b, const Eigen::Vector3d& normal) {
  FaceManifold out;
  const auto [face_b, cos_b] = b.facing(normal);
  const auto [face_a, cos_a] = a.facing(-normal);
  const bool b_refers = cos_b >= cos_a;
  if (std::max(cos_a, cos_b) < kFaceContactCos) return out;
  const WorldHull& ref = b_refers ? b : a;
  const WorldHull& inc = b_refers ? a : b;
  const std::size_t rf = b_refers ? face_b : face_a;
  const Eigen::Vector3d& ref_normal = ref.normals[rf];
  const std::vector<int>& inc_face = (*inc.faces)[inc.facing(-ref_normal).first];
  std::vector<Eigen::Vector3d> poly;
  for (int v : inc_face) poly.push_back(inc.vertices_m[static_cast<std::size_t>(v)]);
  const std::vector<int>& ref_face = (*ref.faces)[rf];
  std::vector<Eigen::Vector3d> clipped;
  for (std::size_t e = 0; e < ref_face.size() && !poly.empty(); ++e) {
    const Eigen::Vector3d& p = ref.vertices_m[static_cast<std::size_t>(ref_face[e])];
    const Eigen::Vector3d& q =
        ref.vertices_m[static_cast<std::size_t>(ref_face[(e + 1) % ref_face.size()])];
    // Counter-clockwise about the outward normal, so (q - p) x normal points out of the face.
    const Eigen::Vector3d side = (q - p).cross(ref_normal);
    clipped.clear();
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Eigen::Vector3d& x = poly[i];
      const Eigen::Vector3d& y = poly[(i + 1) % poly.size()];
      const double dx = side.dot(x - p);
      const double dy = side.dot(y - p);
      if (dx <= 0.0) clipped.push_back(x);
      if ((dx < 0.0 && dy > 0.0) || (dx > 0.0 && dy < 0.0)) {
        clipped.push_back(x + dx / (dx - dy) * (y - x));
      }
    }
    std::swap(poly, clipped);
  }
  for (const Eigen::Vector3d& x : poly) {
    const double depth = ref.offsets_m[rf] - ref_normal.dot(x);
    if (depth > 0.0) out.points.push_back({x, depth});
  }
  if (out.points.empty()) return out;
  std::stable_sort(
      out.points.begin(), out.points.end(),
      [](const ManifoldPoint& p, const ManifoldPoint& q) { return p.depth_m > q.depth_m; });
  out.normal = b_refers ? ref_normal : Eigen::Vector3d(-ref_normal);
  return out;
}

}  // namespace fragsim
