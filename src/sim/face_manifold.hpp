#pragma once
// The contact points of two convex hulls (a convex piece, or a box) touching face on face, made as
// box-box colliders make them. The face of either hull that best faces the other along the contact
// normal is the reference, the other hull's face most opposed to it is clipped to the reference
// face's sides, and what lies below the reference plane is kept, that deep. A piece resting on a
// face then rests on the face's corners rather than pivoting on one point. The world (world.cpp)
// gates it with the collider's own contact and normal, and keeps that one point for an edge or
// corner contact, where this finds no face.

#include <Eigen/Core>
#include <cstddef>
#include <utility>
#include <vector>

namespace fragsim {

// A hull in the world frame, as the face manifold works on it.
struct WorldHull {
  std::vector<Eigen::Vector3d> vertices_m;
  const std::vector<std::vector<int>>* faces = nullptr;  // the body frame's, same indices
  std::vector<Eigen::Vector3d> normals;
  std::vector<double> offsets_m;

  // The face whose outward normal is closest to `direction`, and that cosine.
  std::pair<std::size_t, double> facing(const Eigen::Vector3d& direction) const {
    std::pair<std::size_t, double> best{0, -INFINITY};
    for (std::size_t f = 0; f < normals.size(); ++f) {
      const double c = normals[f].dot(direction);
      if (c > best.second) best = {f, c};
    }
    return best;
  }
};

// `vertices_m`, `normals` and `offsets_m` in the frame of a body at position_m with `rotation`,
// moved to the world. `faces` is kept by address, so it must outlive the hull.
WorldHull place_hull(const Eigen::Vector3d& position_m, const Eigen::Matrix3d& rotation,
                     const std::vector<Eigen::Vector3d>& vertices_m,
                     const std::vector<std::vector<int>>& faces,
                     const std::vector<Eigen::Vector3d>& normals,
                     const std::vector<double>& offsets_m);

// A box of half extents half_m at position_m with `rotation`, as a hull in the world.
WorldHull place_box(const Eigen::Vector3d& position_m, const Eigen::Matrix3d& rotation,
                    const Eigen::Vector3d& half_m);

// Below this cosine between the contact normal and the best face normal, the contact is an edge
// or a corner, not a face, and one point is right.
constexpr double kFaceContactCos = 0.7;

// One contact point of the manifold and how deep it lies below the reference face.
struct ManifoldPoint {
  Eigen::Vector3d position_m;
  double depth_m;
};

// The manifold's points, deepest first (the clipped polygon's order among equal depths), and the
// normal they share, pointing from hull b into hull a (the collider's convention).
struct FaceManifold {
  std::vector<ManifoldPoint> points;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
};

// The face manifold of hull a touching hull b along `normal` (from b into a). No points for an edge
// or corner contact, with no face turned to the normal or nothing left below the reference face
// after clipping.
FaceManifold face_manifold(const WorldHull& a, const WorldHull& b, const Eigen::Vector3d& normal);

}  // namespace fragsim
