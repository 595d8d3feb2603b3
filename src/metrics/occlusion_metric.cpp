#include "metrics/occlusion_metric.hpp"

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>

#include "control/geometry/frustum.hpp"
#include "geometry/camera_box.hpp"
#include "geometry/camera_hull.hpp"

namespace fragsim {

namespace {

// A box cut by one plane keeps at most 7 corners and gains at most 6 cut points; uncut it has 8.
constexpr int kMaxPoints = 14;

// Twice the signed area of the triangle o, a, b, > 0 for a counter-clockwise turn in a y-up frame.
double cross(const ScreenPoint& o, const ScreenPoint& a, const ScreenPoint& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// Andrew's monotone chain over p[0..n), which it sorts in place. Writes the hull's vertices,
// without collinear points or a repeated first vertex, to hull (room for 2 n) and returns their
// count (1 or 2 for a degenerate hull). Insertion sort, because n <= 14 for a box, a few dozen for
// a hull, and nothing may allocate.
int convex_hull(ScreenPoint* p, int n, ScreenPoint* hull) {
  for (int i = 1; i < n; ++i) {
    const ScreenPoint v = p[i];
    int j = i - 1;
    while (j >= 0 && (p[j].x > v.x || (p[j].x == v.x && p[j].y > v.y))) {
      p[j + 1] = p[j];
      --j;
    }
    p[j + 1] = v;
  }
  if (n < 3) {
    std::copy(p, p + n, hull);
    return n;
  }
  int k = 0;
  for (int i = 0; i < n; ++i) {  // lower chain
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p[i]) <= 0.0) --k;
    hull[k++] = p[i];
  }
  for (int i = n - 2, lower = k + 1; i >= 0; --i) {  // upper chain
    while (k >= lower && cross(hull[k - 2], hull[k - 1], p[i]) <= 0.0) --k;
    hull[k++] = p[i];
  }
  return k - 1;  // the last vertex repeats the first
}

// Where a fragment paints, the coverage mask and for a translucent frame also each pixel's
// transmittance, the product of (1 - alpha) over the fragments covering it, multiplied by `keep`
// (1 - this fragment's alpha). Opaque frames leave `transmittance` null and only mark the mask.
struct Paint {
  std::uint8_t* coverage = nullptr;
  double* transmittance = nullptr;
  double keep = 0.0;
};

// Marks the pixels whose centre lies in the closed convex polygon hull[0..n) (pixel units, any
// orientation) and returns their count. Each row's span comes from the polygon's crossings of the
// row's centre line, so a row costs one pass over the (at most 14) edges plus one fill.
int fill_hull(const ScreenPoint* hull, int n, int width_px, int height_px, const Paint& paint) {
  std::uint8_t* coverage = paint.coverage;
  double y_min = hull[0].y;
  double y_max = hull[0].y;
  for (int i = 1; i < n; ++i) {
    y_min = std::min(y_min, hull[i].y);
    y_max = std::max(y_max, hull[i].y);
  }
  // Rows whose centre (row + 0.5) lies in [y_min, y_max], clamped in double before the cast so a
  // vertex far off screen cannot overflow an int.
  const double row_lo = std::max(0.0, std::ceil(y_min - 0.5));
  const double row_hi = std::min(height_px - 1.0, std::floor(y_max - 0.5));
  if (row_lo > row_hi) return 0;
  int own = 0;
  for (int row = static_cast<int>(row_lo); row <= static_cast<int>(row_hi); ++row) {
    const double yc = row + 0.5;
    double x_lo = std::numeric_limits<double>::infinity();
    double x_hi = -std::numeric_limits<double>::infinity();
    for (int i = 0; i < n; ++i) {
      const ScreenPoint& a = hull[i];
      const ScreenPoint& b = hull[i + 1 == n ? 0 : i + 1];
      if ((yc < a.y && yc < b.y) || (yc > a.y && yc > b.y)) continue;
      if (a.y == b.y) {  // a horizontal edge on the centre line is all inside
        x_lo = std::min(x_lo, std::min(a.x, b.x));
        x_hi = std::max(x_hi, std::max(a.x, b.x));
      } else {
        const double x = a.x + (yc - a.y) * (b.x - a.x) / (b.y - a.y);
        x_lo = std::min(x_lo, x);
        x_hi = std::max(x_hi, x);
      }
    }
    const double col_lo = std::max(0.0, std::ceil(x_lo - 0.5));
    const double col_hi = std::min(width_px - 1.0, std::floor(x_hi - 0.5));
    if (col_lo > col_hi) continue;
    const int c0 = static_cast<int>(col_lo);
    const int c1 = static_cast<int>(col_hi);
    std::uint8_t* line = coverage + static_cast<std::ptrdiff_t>(row) * width_px;
    std::fill(line + c0, line + c1 + 1, std::uint8_t{1});
    if (paint.transmittance) {
      double* t = paint.transmittance + static_cast<std::ptrdiff_t>(row) * width_px;
      for (int c = c0; c <= c1; ++c) t[c] *= paint.keep;
    }
    own += c1 - c0 + 1;
  }
  return own;
}

// The view-dependent constants of one step.
struct Projection {
  double near_m = 0.0;
  double tan_x = 0.0;  // half width of the frustum per metre of depth
  double tan_y = 0.0;  // half height per metre of depth
  PixelProjection pixels;

  ScreenPoint project(const Eigen::Vector3d& p) const { return pixels.project(p); }
};

Projection make_projection(const CameraPose& camera, int width_px, int height_px) {
  assert(camera.near_m > 0.0);  // the clip below divides by depths >= near
  const Frustum frustum = camera.frustum();
  return {camera.near_m, frustum.tan_x(), frustum.tan_y(),
          PixelProjection(frustum, width_px, height_px)};
}

// Marks the pixels covered by one fragment's box, clipped at the near plane and projected, and
// returns how many that box covers by itself.
int rasterise(const Projection& pr, const CameraPose& camera, const FragmentState& f, int width_px,
              int height_px, const Paint& coverage) {
  const CameraBox box = camera_box(camera, f);
  // A non-finite state is reported by the simulation's own checks; it must not paint the screen.
  if (!box.finite()) return 0;
  const Eigen::Vector3d& c = box.centre_m;
  const Eigen::Matrix3d& axes = box.half_axes_m;

  // Cheap culling. The box lies wholly on the outer side of the near plane or of a side plane
  // (n . p > d for all its points) when n . c - sum_k |n . axis_k| > d.
  const auto outside = [&](const Eigen::Vector3d& n, double d) {
    return n.dot(c) - (axes.transpose() * n).cwiseAbs().sum() > d;
  };
  if (outside({0.0, 0.0, -1.0}, -pr.near_m)) return 0;  // z < near everywhere
  if (outside({1.0, 0.0, -pr.tan_x}, 0.0) || outside({-1.0, 0.0, -pr.tan_x}, 0.0) ||
      outside({0.0, 1.0, -pr.tan_y}, 0.0) || outside({0.0, -1.0, -pr.tan_y}, 0.0)) {
    return 0;
  }

  // Corner i and corner i | (1 << k) share the edge along axis k (CameraBox::corner).
  const std::array<Eigen::Vector3d, 8> corner = box.corners();
  // The part with z >= near is the convex polytope spanned by the corners in front of the plane
  // and the points where the 12 edges cross it; its projection is the hull of theirs.
  std::array<ScreenPoint, kMaxPoints> points;
  int n = 0;
  for (int i = 0; i < 8; ++i) {
    if (corner[i].z() >= pr.near_m) points[n++] = pr.project(corner[i]);
  }
  if (n < 8) {
    for (int i = 0; i < 8; ++i) {
      for (int k = 0; k < 3; ++k) {
        const int j = i | (1 << k);
        if (j == i) continue;  // each edge once, from its corner with bit k clear
        const Eigen::Vector3d& a = corner[i];
        const Eigen::Vector3d& b = corner[j];
        if ((a.z() >= pr.near_m) == (b.z() >= pr.near_m)) continue;
        const double t = (pr.near_m - a.z()) / (b.z() - a.z());
        Eigen::Vector3d p = a + t * (b - a);
        p.z() = pr.near_m;  // exactly on the plane, whatever the rounding of t
        assert(n < kMaxPoints);
        points[n++] = pr.project(p);
      }
    }
  }
  if (n == 0) return 0;
  std::array<ScreenPoint, 2 * kMaxPoints> hull;
  const int h = convex_hull(points.data(), n, hull.data());
  return fill_hull(hull.data(), h, width_px, height_px, coverage);
}

// Marks the pixels covered by one convex piece (FragmentState::shape), clipped at the near plane
// and projected as the box above is, and returns how many it covers by itself. `cam_vertices` and
// `points` are the caller's scratch, so a step allocates nothing once they have grown.
int rasterise_hull(const Projection& pr, const CameraPose& camera, const FragmentState& f,
                   int width_px, int height_px, const Paint& coverage,
                   std::vector<Eigen::Vector3d>& cam_vertices, std::vector<ScreenPoint>& points) {
  hull_camera_vertices(camera, f, cam_vertices);
  for (const Eigen::Vector3d& v : cam_vertices) {
    if (!v.allFinite()) return 0;  // reported by the simulation's own checks
  }
  // Cheap culling if every vertex is on the outer side of the near plane or of one side plane.
  const auto outside = [&](const Eigen::Vector3d& n, double d) {
    for (const Eigen::Vector3d& v : cam_vertices) {
      if (!(n.dot(v) > d)) return false;
    }
    return true;
  };
  if (outside({0.0, 0.0, -1.0}, -pr.near_m)) return 0;
  if (outside({1.0, 0.0, -pr.tan_x}, 0.0) || outside({-1.0, 0.0, -pr.tan_x}, 0.0) ||
      outside({0.0, 1.0, -pr.tan_y}, 0.0) || outside({0.0, -1.0, -pr.tan_y}, 0.0)) {
    return 0;
  }
  // As for the box, the part with z >= near is spanned by the vertices in front of the plane and
  // the points where the hull's edges cross it.
  points.clear();
  for (const Eigen::Vector3d& v : cam_vertices) {
    if (v.z() >= pr.near_m) points.push_back(pr.project(v));
  }
  if (points.size() < cam_vertices.size()) {
    for (const std::vector<int>& face : f.shape->faces) {
      for (std::size_t k = 0; k < face.size(); ++k) {
        const int ia = face[k];
        const int ib = face[k + 1 == face.size() ? 0 : k + 1];
        // Every edge borders two faces, once in each direction, so take it once.
        if (ia > ib) continue;
        const Eigen::Vector3d& a = cam_vertices[static_cast<std::size_t>(ia)];
        const Eigen::Vector3d& b = cam_vertices[static_cast<std::size_t>(ib)];
        if ((a.z() >= pr.near_m) == (b.z() >= pr.near_m)) continue;
        const double t = (pr.near_m - a.z()) / (b.z() - a.z());
        Eigen::Vector3d p = a + t * (b - a);
        p.z() = pr.near_m;
        points.push_back(pr.project(p));
      }
    }
  }
  if (points.empty()) return 0;
  const std::size_t n = points.size();
  points.resize(3 * n);  // the hull's room (2 n) after the n points
  const int h = convex_hull(points.data(), static_cast<int>(n), points.data() + n);
  return fill_hull(points.data() + n, h, width_px, height_px, coverage);
}

}  // namespace

OcclusionMetric::OcclusionMetric(const MetricsDef& def)
    : grid_width_px_(def.grid_width_px), central_fraction_(def.central_share) {
  // The scene file rejects other values; these are our invariants, not user errors.
  assert(grid_width_px_ >= 1);
  assert(central_fraction_ > 0.0 && central_fraction_ <= 1.0);
}

void OcclusionMetric::begin(const RunInfo& info, const StepSnapshot& initial) {
  assert(initial.camera.aspect > 0.0);
  width_px_ = grid_width_px_;
  height_px_ = std::max(1, static_cast<int>(std::lround(width_px_ / initial.camera.aspect)));
  // Equal margins on both sides keep the region exactly centred, so its size has the grid's
  // parity (the nearest such to central_share of the grid); it keeps at least one pixel.
  const auto margin = [this](int n) {
    const int m = static_cast<int>(std::lround(0.5 * n * (1.0 - central_fraction_)));
    return std::clamp(m, 0, (n - 1) / 2);
  };
  central_x0_ = margin(width_px_);
  central_x1_ = width_px_ - central_x0_;
  central_y0_ = margin(height_px_);
  central_y1_ = height_px_ - central_y0_;
  coverage_.assign(static_cast<std::size_t>(width_px_) * static_cast<std::size_t>(height_px_), 0);
  viewport_share_.clear();
  central_share_.clear();
  viewport_share_.reserve(static_cast<std::size_t>(std::max(0, info.step_count)));
  central_share_.reserve(static_cast<std::size_t>(std::max(0, info.step_count)));
  single_max_ = 0.0;
}

void OcclusionMetric::observe(const StepSnapshot& snap) {
  assert(width_px_ > 0 && "begin() sizes the raster");
  std::fill(coverage_.begin(), coverage_.end(), std::uint8_t{0});
  const double pixels = static_cast<double>(coverage_.size());
  const Projection pr = make_projection(snap.camera, width_px_, height_px_);
  // A frame with opacities (fade) composites. A pixel is covered by 1 - prod(1 - alpha) of the
  // fragments over it, and a fragment's own share counts by its alpha. Without opacities the mask
  // alone is counted, so an opaque run's numbers are plain coverage to the bit.
  const bool translucent = !snap.opacity.empty();
  assert(!translucent || snap.opacity.size() == snap.fragments.size());
  if (translucent) transmittance_.assign(coverage_.size(), 1.0);
  int own_max = 0;
  double own_share_max = 0.0;
  for (std::size_t i = 0; i < snap.fragments.size(); ++i) {
    const FragmentState& f = snap.fragments[i];
    Paint paint{coverage_.data(), nullptr, 0.0};
    double alpha = 1.0;
    if (translucent) {
      alpha = snap.opacity[i];
      if (!(alpha > 0.0)) continue;  // invisible, so nothing is drawn
      paint.transmittance = transmittance_.data();
      paint.keep = 1.0 - alpha;
    }
    const int own = f.shape ? rasterise_hull(pr, snap.camera, f, width_px_, height_px_, paint,
                                             hull_vertices_, hull_points_)
                            : rasterise(pr, snap.camera, f, width_px_, height_px_, paint);
    own_max = std::max(own_max, own);
    own_share_max = std::max(own_share_max, own * alpha);
  }

  const auto count = [this](int x0, int x1, int y0, int y1) {
    int covered = 0;
    for (int row = y0; row < y1; ++row) {
      const std::uint8_t* line = coverage_.data() + static_cast<std::ptrdiff_t>(row) * width_px_;
      covered += std::accumulate(line + x0, line + x1, 0);
    }
    return covered;
  };
  const auto composite = [this](int x0, int x1, int y0, int y1) {
    double covered = 0.0;
    for (int row = y0; row < y1; ++row) {
      const double* line = transmittance_.data() + static_cast<std::ptrdiff_t>(row) * width_px_;
      for (int col = x0; col < x1; ++col) covered += 1.0 - line[col];
    }
    return covered;
  };
  const double central_pixels =
      static_cast<double>(central_x1_ - central_x0_) * (central_y1_ - central_y0_);
  if (translucent) {
    viewport_share_.push_back(composite(0, width_px_, 0, height_px_) / pixels);
    central_share_.push_back(composite(central_x0_, central_x1_, central_y0_, central_y1_) /
                             central_pixels);
    single_max_ = std::max(single_max_, own_share_max / pixels);
    return;
  }
  const int covered = count(0, width_px_, 0, height_px_);
  const int central = count(central_x0_, central_x1_, central_y0_, central_y1_);
  viewport_share_.push_back(covered / pixels);
  central_share_.push_back(central / central_pixels);
  single_max_ = std::max(single_max_, own_max / pixels);
}

void OcclusionMetric::fill(RunSummary& s) const {
  const auto mean = [](const std::vector<double>& v) {
    return v.empty() ? 0.0
                     : std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size());
  };
  const auto max = [](const std::vector<double>& v) {
    return v.empty() ? 0.0 : *std::max_element(v.begin(), v.end());
  };
  s.occlusion.mean = mean(viewport_share_);
  s.occlusion.max = max(viewport_share_);
  s.occlusion.central_mean = mean(central_share_);
  s.occlusion.central_max = max(central_share_);
  s.occlusion.single_fragment_max = single_max_;
}

}  // namespace fragsim
