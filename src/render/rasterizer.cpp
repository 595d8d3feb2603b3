#include "render/rasterizer.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <limits>

namespace fragsim {

namespace {

// The pixel range whose centres (i + 0.5) lie in [lo, hi], clamped to [0, size) in double before
// the cast so a coordinate far off screen cannot overflow an int. Empty when first > last.
struct PixelRange {
  int first = 0;
  int last = -1;
};

PixelRange centres_in(double lo, double hi, int size) {
  const double first = std::max(0.0, std::ceil(lo - 0.5));
  const double last = std::min(size - 1.0, std::floor(hi - 0.5));
  if (!(first <= last)) return {};
  return {static_cast<int>(first), static_cast<int>(last)};
}

// Twice the signed area of a, b, q; in screen axes (y down) > 0 means a clockwise turn.
double edge(const ScreenPoint& a, const ScreenPoint& b, double qx, double qy) {
  return (b.x - a.x) * (qy - a.y) - (b.y - a.y) * (qx - a.x);
}

// Keeps the part of segment a-b with z >= plane_z (keep_greater) or z <= plane_z; false if none.
bool clip_segment_z(Eigen::Vector3d& a, Eigen::Vector3d& b, double plane_z, bool keep_greater) {
  const auto inside = [&](const Eigen::Vector3d& p) {
    return keep_greater ? p.z() >= plane_z : p.z() <= plane_z;
  };
  const bool a_in = inside(a);
  const bool b_in = inside(b);
  if (a_in && b_in) return true;
  if (!a_in && !b_in) return false;
  Eigen::Vector3d& out = a_in ? b : a;
  const Eigen::Vector3d& in = a_in ? a : b;
  const double t = (plane_z - in.z()) / (out.z() - in.z());
  out = in + t * (out - in);
  out.z() = plane_z;
  return true;
}

}  // namespace

int clip_polygon_z(const Eigen::Vector3d* in, int n, double plane_z, bool keep_greater,
                   Eigen::Vector3d* out) {
  const auto inside = [&](const Eigen::Vector3d& p) {
    return keep_greater ? p.z() >= plane_z : p.z() <= plane_z;
  };
  int m = 0;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d& cur = in[i];
    const Eigen::Vector3d& next = in[i + 1 == n ? 0 : i + 1];
    const bool cur_in = inside(cur);
    if (cur_in) out[m++] = cur;
    if (cur_in != inside(next)) {
      const double t = (plane_z - cur.z()) / (next.z() - cur.z());
      Eigen::Vector3d p = cur + t * (next - cur);
      p.z() = plane_z;  // exactly on the plane, whatever the rounding of t
      out[m++] = p;
    }
  }
  assert(m <= n + 1);
  return m;
}

void Rasterizer::begin(Image& image, const CameraPose& camera) {
  assert(camera.near_m > 0.0 && camera.far_m > camera.near_m);
  image_ = &image;
  camera_ = camera;
  width_ = image.width();
  height_ = image.height();
  projection_ = PixelProjection(camera.frustum(), width_, height_);
  inverse_depth_.assign(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_), 0.0f);
}

void Rasterizer::fill_triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                               const Eigen::Vector3d& c, Rgb colour) {
  assert(image_ && "begin() starts a frame");
  if (!a.allFinite() || !b.allFinite() || !c.allFinite()) return;
  // Each plane adds at most one corner (3 -> 4 -> 5).
  std::array<Eigen::Vector3d, 5> poly{a, b, c};
  std::array<Eigen::Vector3d, 5> tmp;
  int n = 3;
  const double near = camera_.near_m;
  const double far = camera_.far_m;
  if (std::min({a.z(), b.z(), c.z()}) < near) {
    n = clip_polygon_z(poly.data(), n, near, true, tmp.data());
    std::copy(tmp.begin(), tmp.begin() + n, poly.begin());
  }
  if (n >= 3 && std::max({a.z(), b.z(), c.z()}) > far) {
    n = clip_polygon_z(poly.data(), n, far, false, tmp.data());
    std::copy(tmp.begin(), tmp.begin() + n, poly.begin());
  }
  if (n < 3) return;
  // The perspective divide; 1 / z is affine in screen space, so it is interpolated linearly.
  std::array<ScreenPoint, 5> p;
  std::array<double, 5> inv_z;
  for (int i = 0; i < n; ++i) {
    p[i] = project(poly[i]);
    inv_z[i] = 1.0 / poly[i].z();
  }
  // The clipped polygon is convex; fan it from its first corner.
  for (int i = 1; i + 1 < n; ++i) {
    const std::array<ScreenPoint, 3> tri{p[0], p[i], p[i + 1]};
    const std::array<double, 3> w{inv_z[0], inv_z[i], inv_z[i + 1]};
    fill_projected(tri.data(), w.data(), colour);
  }
}

bool dither_shows(int col, int row, float opacity) {
  // The 4x4 Bayer matrix puts neighbouring thresholds far apart, so any opacity gives an even,
  // regular pattern rather than clumps.
  static constexpr int kBayer[4][4] = {
      {0, 8, 2, 10}, {12, 4, 14, 6}, {3, 11, 1, 9}, {15, 7, 13, 5}};
  const int b = kBayer[row & 3][col & 3];
  return opacity * 16.0f > static_cast<float>(b) + 0.5f;
}

void Rasterizer::fill_projected(const ScreenPoint* p, const double* inv_z, Rgb colour) {
  const double area = edge(p[0], p[1], p[2].x, p[2].y);
  if (!(std::abs(area) > 0.0) || !std::isfinite(area)) return;  // edge-on or degenerate
  const double sign = area > 0.0 ? 1.0 : -1.0;
  const double inv_area = 1.0 / std::abs(area);
  const PixelRange rows =
      centres_in(std::min({p[0].y, p[1].y, p[2].y}), std::max({p[0].y, p[1].y, p[2].y}), height_);
  // The weight of corner i is the signed area over the opposite edge (a, b), >= 0 inside (edges
  // included), and along a row it is affine in x, w_i = c_i + slope_i x.
  std::array<double, 3> slope;
  for (int i = 0; i < 3; ++i) {
    const ScreenPoint& a = p[(i + 1) % 3];
    const ScreenPoint& b = p[(i + 2) % 3];
    slope[i] = -sign * (b.y - a.y);
  }
  for (int row = rows.first; row <= rows.last; ++row) {
    const double yc = row + 0.5;
    std::array<double, 3> c;
    double x_lo = -std::numeric_limits<double>::infinity();
    double x_hi = std::numeric_limits<double>::infinity();
    bool empty = false;
    for (int i = 0; i < 3; ++i) {
      const ScreenPoint& a = p[(i + 1) % 3];
      const ScreenPoint& b = p[(i + 2) % 3];
      c[i] = sign * ((b.x - a.x) * (yc - a.y) + (b.y - a.y) * a.x);
      if (slope[i] > 0.0) {
        x_lo = std::max(x_lo, -c[i] / slope[i]);
      } else if (slope[i] < 0.0) {
        x_hi = std::min(x_hi, -c[i] / slope[i]);
      } else if (c[i] < 0.0) {
        empty = true;  // a horizontal edge with the row on its outer side
      }
    }
    if (empty) continue;
    const PixelRange cols = centres_in(x_lo, x_hi, width_);
    float* depth = inverse_depth_.data() + static_cast<std::ptrdiff_t>(row) * width_;
    for (int col = cols.first; col <= cols.last; ++col) {
      const double xc = col + 0.5;
      const double w0 = c[0] + slope[0] * xc;
      const double w1 = c[1] + slope[1] * xc;
      const double w2 = c[2] + slope[2] * xc;
      const float d =
          static_cast<float>((w0 * inv_z[0] + w1 * inv_z[1] + w2 * inv_z[2]) * inv_area);
      if (d > depth[col] && (opacity_ >= 1.0f || dither_shows(col, row, opacity_))) {
        depth[col] = d;
        image_->set(col, row, colour);
      }
    }
  }
}

bool Rasterizer::draw_segment(const Eigen::Vector3d& a, const Eigen::Vector3d& b, Rgb colour,
                              int thickness_px, ScreenPoint* a_px, ScreenPoint* b_px) {
  assert(image_ && "begin() starts a frame");
  if (!a.allFinite() || !b.allFinite()) return false;
  Eigen::Vector3d p = a;
  Eigen::Vector3d q = b;
  if (!clip_segment_z(p, q, camera_.near_m, true)) return false;
  if (!clip_segment_z(p, q, camera_.far_m, false)) return false;
  const ScreenPoint pa = project(p);
  const ScreenPoint pb = project(q);
  draw_line(*image_, pa, pb, colour, thickness_px);
  if (a_px) *a_px = pa;
  if (b_px) *b_px = pb;
  return true;
}

void draw_line(Image& image, ScreenPoint a, ScreenPoint b, Rgb colour, int thickness_px) {
  if (!std::isfinite(a.x) || !std::isfinite(a.y) || !std::isfinite(b.x) || !std::isfinite(b.y)) {
    return;
  }
  thickness_px = std::max(1, thickness_px);
  // Liang-Barsky against the image grown by the pen, so a line far off screen costs nothing.
  const double margin = thickness_px;
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  double t0 = 0.0;
  double t1 = 1.0;
  const auto clip = [&](double p, double q) {  // keeps the part with p t <= q
    if (p == 0.0) return q >= 0.0;
    const double r = q / p;
    if (p < 0.0) {
      if (r > t1) return false;
      t0 = std::max(t0, r);
    } else {
      if (r < t0) return false;
      t1 = std::min(t1, r);
    }
    return true;
  };
  if (!clip(-dx, a.x + margin) || !clip(dx, image.width() + margin - a.x) ||
      !clip(-dy, a.y + margin) || !clip(dy, image.height() + margin - a.y)) {
    return;
  }
  const ScreenPoint s{a.x + t0 * dx, a.y + t0 * dy};
  const ScreenPoint e{a.x + t1 * dx, a.y + t1 * dy};
  const int steps =
      std::max(1, static_cast<int>(std::ceil(std::max(std::abs(e.x - s.x), std::abs(e.y - s.y)))));
  const int lo = -(thickness_px - 1) / 2;
  const int hi = thickness_px / 2;
  for (int i = 0; i <= steps; ++i) {
    const double t = static_cast<double>(i) / steps;
    const int col = static_cast<int>(std::floor(s.x + t * (e.x - s.x)));
    const int row = static_cast<int>(std::floor(s.y + t * (e.y - s.y)));
    image.fill_rect(col + lo, row + lo, col + hi + 1, row + hi + 1, colour);
  }
}

void draw_rect_outline(Image& image, int x0, int y0, int x1, int y1, Rgb colour, int thickness_px) {
  const int t = std::max(1, thickness_px);
  image.fill_rect(x0, y0, x1, y0 + t, colour);
  image.fill_rect(x0, y1 - t, x1, y1, colour);
  image.fill_rect(x0, y0, x0 + t, y1, colour);
  image.fill_rect(x1 - t, y0, x1, y1, colour);
}

}  // namespace fragsim
