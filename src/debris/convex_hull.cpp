#include "debris/convex_hull.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <string>
#include <utility>

extern "C" {
#include <libqhull_r/qhull_ra.h>
}

namespace fragsim {
namespace {

// Qhull's own messages go to a stream; ours carry the reason in one line, so its text is dropped.
struct NullStream {
  FILE* f = std::fopen("/dev/null", "w");
  ~NullStream() {
    if (f) std::fclose(f);
  }
};

// Qhull's state, freed however the hull ends.
struct Qhull {
  qhT qh;
  explicit Qhull(FILE* err) { qh_zero(&qh, err); }
  ~Qhull() {
    qh_freeqhull(&qh, !qh_ALL);
    int curlong = 0;
    int totlong = 0;
    qh_memfreeshort(&qh, &curlong, &totlong);
  }
};

// A merged facet's vertices come as a set, not a loop, so they are sorted by angle about the
// facet's centre, counter-clockwise seen along the outward normal.
std::vector<int> loop_about(const std::vector<Eigen::Vector3d>& pts, std::vector<int> ids,
                            const Eigen::Vector3d& normal) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (int i : ids) c += pts[i];
  c /= static_cast<double>(ids.size());
  const Eigen::Vector3d u = (pts[ids.front()] - c).normalized();
  const Eigen::Vector3d w = normal.cross(u);
  // Angles are kept beside the ids, not in a table over all points, as one such table per facet
  // makes a hull of 500,000 vertices quadratic. Sorted by angle alone, as that table would be, so
  // the order (ties included) is the one it would give.
  std::vector<std::pair<double, int>> by_angle;
  by_angle.reserve(ids.size());
  for (int i : ids) by_angle.emplace_back(std::atan2((pts[i] - c).dot(w), (pts[i] - c).dot(u)), i);
  std::sort(by_angle.begin(), by_angle.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  for (std::size_t k = 0; k < ids.size(); ++k) ids[k] = by_angle[k].second;
  return ids;
}

}  // namespace

MassProperties polyhedron_mass(const std::vector<Eigen::Vector3d>& vertices_m,
                               const std::vector<std::vector<int>>& faces) {
  // Tetrahedra from the vertices' mean g, which lies inside a convex solid, keep every term small
  // and of one sign. For a tetrahedron (g, g+a, g+b, g+c) with A = [a b c], the second moment
  // about g is det(A) A K A^T with K = (1 + I) / 120 (Tonon's closed form, in matrix form).
  Eigen::Vector3d g = Eigen::Vector3d::Zero();
  for (const auto& v : vertices_m) g += v;
  g /= static_cast<double>(vertices_m.size());
  Eigen::Matrix3d k = Eigen::Matrix3d::Constant(1.0 / 120.0);
  k.diagonal().setConstant(2.0 / 120.0);
  double six_volume = 0.0;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();  // sum of det * (a + b + c) / 4
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (const auto& f : faces) {
    for (std::size_t i = 1; i + 1 < f.size(); ++i) {
      Eigen::Matrix3d a;
      a.col(0) = vertices_m[f[0]] - g;
      a.col(1) = vertices_m[f[i]] - g;
      a.col(2) = vertices_m[f[i + 1]] - g;
      const double det = a.determinant();
      six_volume += det;
      first += det * (a.col(0) + a.col(1) + a.col(2)) / 4.0;
      second += det * a * k * a.transpose();
    }
  }
  MassProperties m;
  m.volume_m3 = six_volume / 6.0;
  if (!(m.volume_m3 > 0.0)) return m;
  const Eigen::Vector3d d = first / six_volume;  // centre of mass relative to g
  m.centre_m = g + d;
  const Eigen::Matrix3d c = second - m.volume_m3 * d * d.transpose();  // about the centre
  m.inertia_per_kg_m2 = (c.trace() * Eigen::Matrix3d::Identity() - c) / m.volume_m3;
  return m;
}

std::shared_ptr<ConvexShape> shape_of_polyhedron(const std::vector<Eigen::Vector3d>& vertices_m,
                                                 const std::vector<std::vector<int>>& faces,
                                                 Eigen::Vector3d* centre_m) {
  const MassProperties m = polyhedron_mass(vertices_m, faces);
  auto s = std::make_shared<ConvexShape>();
  s->volume_m3 = m.volume_m3;
  s->inertia_per_kg_m2 = m.inertia_per_kg_m2;
  s->faces = faces;
  for (const auto& v : vertices_m) {
    s->vertices_m.push_back(v - m.centre_m);
    s->radius_m = std::max(s->radius_m, s->vertices_m.back().norm());
    s->half_extents_m = s->half_extents_m.cwiseMax(s->vertices_m.back().cwiseAbs());
  }
  for (const auto& f : faces) {
    // Newell's normal is the polygon's area vector, exact for a planar loop and the best fit of a
    // nearly planar one.
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < f.size(); ++i) {
      n += s->vertices_m[f[i]].cross(s->vertices_m[f[(i + 1) % f.size()]]);
    }
    n.normalize();
    double d = -std::numeric_limits<double>::infinity();
    for (int i : f) d = std::max(d, n.dot(s->vertices_m[i]));
    s->normals.push_back(n);
    s->offsets_m.push_back(d);
  }
  if (centre_m) *centre_m = m.centre_m;
  return s;
}

std::shared_ptr<ConvexShape> scaled_shape(const ConvexShape& shape, double s) {
  auto out = std::make_shared<ConvexShape>(shape);
  for (auto& v : out->vertices_m) v *= s;
  for (auto& d : out->offsets_m) d *= s;
  out->volume_m3 *= s * s * s;
  out->inertia_per_kg_m2 *= s * s;
  out->radius_m *= s;
  out->half_extents_m *= s;
  return out;
}

namespace {

// The hull's vertices (input points) and faces, counter-clockwise from outside.
struct Polyhedron {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<std::vector<int>> faces;
};

Polyhedron qhull_of(const std::vector<Eigen::Vector3d>& points_m) {
  std::vector<coordT> coords;
  coords.reserve(3 * points_m.size());
  for (const auto& p : points_m) coords.insert(coords.end(), {p.x(), p.y(), p.z()});
  NullStream sink;
  Qhull q(sink.f);
  qhT* qh = &q.qh;
  // Default options merge coplanar facets (C-0, Qx), so a cube has six square faces.
  char options[] = "qhull";
  const int status = qh_new_qhull(qh, 3, static_cast<int>(points_m.size()), coords.data(), False,
                                  options, nullptr, sink.f);
  if (status != 0) throw DegenerateHull("the points are flat or collinear (no hull with volume)");

  std::vector<int> index_of(points_m.size(), -1);  // input point -> hull vertex
  Polyhedron out;
  facetT* facet;
  vertexT* vertex;
  vertexT** vertexp;
  FORALLfacets {
    std::vector<int> ids;
    FOREACHvertex_(facet->vertices) {
      const int p = qh_pointid(qh, vertex->point);
      if (index_of[p] < 0) {
        index_of[p] = static_cast<int>(out.vertices.size());
        out.vertices.push_back(points_m[p]);
      }
      ids.push_back(index_of[p]);
    }
    const Eigen::Vector3d normal(facet->normal[0], facet->normal[1], facet->normal[2]);
    out.faces.push_back(loop_about(out.vertices, std::move(ids), normal));
  }
  return out;
}

// At most `n` of the vertices, well spread over the hull: first the support point along each of n
// directions of a Fibonacci lattice on the sphere (ties to the first vertex), then, while fewer
// than n (a hull with sharp corners gives many directions the same vertex), the vertex farthest
// from those chosen.
std::vector<Eigen::Vector3d> spread_subset(const std::vector<Eigen::Vector3d>& v, int n) {
  const double golden_angle = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
  std::vector<char> chosen(v.size(), 0);
  std::vector<int> order;
  for (int i = 0; i < n; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / n;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const Eigen::Vector3d u(r * std::cos(golden_angle * i), r * std::sin(golden_angle * i), z);
    std::size_t best = 0;
    double best_d = -std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < v.size(); ++k) {
      const double d = u.dot(v[k]);
      if (d > best_d) {
        best_d = d;
        best = k;
      }
    }
    if (!chosen[best]) {
      chosen[best] = 1;
      order.push_back(static_cast<int>(best));
    }
  }
  std::vector<double> gap2(v.size(), std::numeric_limits<double>::infinity());
  for (int c : order) {
    for (std::size_t k = 0; k < v.size(); ++k)
      gap2[k] = std::min(gap2[k], (v[k] - v[c]).squaredNorm());
  }
  while (static_cast<int>(order.size()) < n) {
    const auto far = std::max_element(gap2.begin(), gap2.end());
    if (!(*far > 0.0)) break;
    const int c = static_cast<int>(far - gap2.begin());
    order.push_back(c);
    for (std::size_t k = 0; k < v.size(); ++k)
      gap2[k] = std::min(gap2[k], (v[k] - v[c]).squaredNorm());
  }
  std::vector<Eigen::Vector3d> out;
  out.reserve(order.size());
  for (int c : order) out.push_back(v[static_cast<std::size_t>(c)]);
  return out;
}

}  // namespace

HullPiece convex_hull(const std::vector<Eigen::Vector3d>& points_m) {
  for (const auto& p : points_m) {
    if (!p.allFinite()) throw DegenerateHull("a vertex is not finite");
  }
  if (points_m.size() < 4) {
    throw DegenerateHull(std::to_string(points_m.size()) + " points: a solid needs at least 4");
  }
  Polyhedron hull = qhull_of(points_m);
  HullPiece out;
  if (hull.vertices.size() > static_cast<std::size_t>(kMaxHullVertices)) {
    out.full_vertices = static_cast<int>(hull.vertices.size());
    out.full_volume_m3 = polyhedron_mass(hull.vertices, hull.faces).volume_m3;
    hull = qhull_of(spread_subset(hull.vertices, kMaxHullVertices));
  }
  auto shape = shape_of_polyhedron(hull.vertices, hull.faces, &out.centre_m);
  if (!(shape->volume_m3 >= kMinHullVolume_m3)) {
    char v[32];
    std::snprintf(v, sizeof v, "%.3g", shape->volume_m3);
    throw DegenerateHull(std::string("hull volume ") + v + " m^3: below 1e-12 m^3");
  }
  out.shape = std::move(shape);
  return out;
}

}  // namespace fragsim
