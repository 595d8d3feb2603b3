#include "render/frame_renderer.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

#include "geometry/camera_box.hpp"
#include "geometry/camera_hull.hpp"

namespace fragsim {

namespace {

// Lit from above, a little left and behind a camera looking down -z.
const Eigen::Vector3d kLight = Eigen::Vector3d(-0.35, 1.0, 0.45).normalized();
constexpr double kAmbient = 0.3;

constexpr Rgb kSkyZenith{96, 140, 200};
constexpr Rgb kSkyHorizon{200, 214, 230};
constexpr Rgb kGroundLight{158, 160, 148};
constexpr Rgb kGroundDark{112, 118, 106};

constexpr double kCheckerM = 1.0;  // ground squares

std::uint8_t channel(double v) {
  return static_cast<std::uint8_t>(std::clamp(v, 0.0, 255.0) + 0.5);
}

Rgb scaled(Rgb c, double k) {
  return {channel(c.r * k), channel(c.g * k), channel(c.b * k)};
}

// A 32-bit integer hash (the "lowbias32" mixer), well spread and the same on every machine.
std::uint32_t hash32(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

double unit(std::uint32_t h) {
  return (h & 0xffffU) / 65535.0;
}

Rgb hsv(double hue_deg, double sat, double val) {
  const double c = val * sat;
  const double hp = hue_deg / 60.0;
  const double x = c * (1.0 - std::abs(std::fmod(hp, 2.0) - 1.0));
  double r = 0.0;
  double g = 0.0;
  double b = 0.0;
  switch (static_cast<int>(hp)) {  // the hue's sextant; 0 <= hp < 6
    case 0:
      r = c;
      g = x;
      break;
    case 1:
      r = x;
      g = c;
      break;
    case 2:
      g = c;
      b = x;
      break;
    case 3:
      g = x;
      b = c;
      break;
    case 4:
      r = x;
      b = c;
      break;
    default:
      r = c;
      b = x;
      break;
  }
  const double m = val - c;
  return {channel(255.0 * (r + m)), channel(255.0 * (g + m)), channel(255.0 * (b + m))};
}

}  // namespace

Rgb fragment_colour(int index) {
  const std::uint32_t h = hash32(static_cast<std::uint32_t>(index) + 0x9e3779b9U);
  // Debris hues from red to yellow, varied in saturation and brightness.
  return hsv(10.0 + 40.0 * unit(h), 0.55 + 0.35 * unit(h >> 16), 0.7 + 0.3 * unit(hash32(h)));
}

Rgb shaded_colour(Rgb base, const Eigen::Vector3d& world_normal) {
  return scaled(base, kAmbient + (1.0 - kAmbient) * std::max(0.0, world_normal.dot(kLight)));
}

FrameRenderer::FrameRenderer(const Scene& scene, const FrameStyle& style)
    : style_(style),
      ground_(scene.ground.enabled),
      ground_height_m_(scene.ground.height_m),
      central_share_(scene.metrics.central_share),
      line_px_(std::max(1, static_cast<int>(std::lround(style.height_px / 360.0)))) {
  assert(style_.width_px >= 1 && style_.height_px >= 1);
}

void FrameRenderer::draw_background(Image& image, const CameraPose& camera) {
  const Rasterizer& r = raster_;
  // A ground pixel's footprint along the view grows as z^2 / (pixels per unit slope * height);
  // once it nears a checker square the squares would alias, so they fade to their mean.
  const double eye_height_m = std::max(std::abs(camera.eye_m.y() - ground_height_m_), 1e-3);
  const double px_per_slope = r.projection().scale_y_px();
  const Eigen::Vector3d light(kGroundLight.r, kGroundLight.g, kGroundLight.b);
  const Eigen::Vector3d dark(kGroundDark.r, kGroundDark.g, kGroundDark.b);
  const Eigen::Vector3d mean = 0.5 * (light + dark);
  const Eigen::Vector3d horizon(kSkyHorizon.r, kSkyHorizon.g, kSkyHorizon.b);
  const Eigen::Vector3d zenith(kSkyZenith.r, kSkyZenith.g, kSkyZenith.b);
  const auto rgb = [](const Eigen::Vector3d& c) {
    return Rgb{channel(c.x()), channel(c.y()), channel(c.z())};
  };
  // The world direction through a pixel centre (its camera-space z is 1, so the distance along it
  // to the ground is the depth) is affine in the column, one step per row and column.
  const Eigen::Vector3d d00 = r.pixel_direction(0, 0);
  const Eigen::Vector3d d11 = r.pixel_direction(1, 1);
  const Eigen::Vector3d col_step = (d11.x() - d00.x()) * camera.right;
  for (int row = 0; row < r.height(); ++row) {
    const Eigen::Vector3d d = r.pixel_direction(0, row);
    const Eigen::Vector3d row_start = d.x() * camera.right + d.y() * camera.up + camera.forward;
    for (int col = 0; col < r.width(); ++col) {
      const Eigen::Vector3d dir = row_start + col * col_step;
      if (ground_ && dir.y() != 0.0) {
        const double z = (ground_height_m_ - camera.eye_m.y()) / dir.y();
        if (z >= camera.near_m && z <= camera.far_m) {
          const double hx = camera.eye_m.x() + z * dir.x();
          const double hz = camera.eye_m.z() + z * dir.z();
          // Parity in double, so no cast can overflow however far the far plane lies.
          const bool odd =
              std::fmod(std::floor(hx / kCheckerM) + std::floor(hz / kCheckerM), 2.0) != 0.0;
          const double footprint_m = z * z / (px_per_slope * eye_height_m);
          const double fade = std::min(footprint_m / kCheckerM, 1.0);
          const double haze = 1.0 - std::exp(-z / 150.0);  // toward the horizon's colour
          const Eigen::Vector3d ground = (odd ? dark : light) * (1.0 - fade) + mean * fade;
          raster_.write_if_nearer(col, row, static_cast<float>(1.0 / z),
                                  rgb(ground * (1.0 - haze) + horizon * haze));
          continue;
        }
      }
      const double elevation = std::clamp(dir.y() / dir.norm(), 0.0, 1.0);
      const double t = std::sqrt(elevation);
      image.set(col, row, rgb(horizon * (1.0 - t) + zenith * t));
    }
  }
}

namespace {

// Whether face (k, s) of the box (the one across +-axis k) faces the eye at the origin.
bool faces_eye(const CameraBox& b, int k, double s) {
  return (s * b.dirs.col(k)).dot(b.centre_m + s * b.half_axes_m.col(k)) < 0.0;
}

// The box seen from `cam`, or nothing when it is wholly before the near plane or beyond the far
// one, wholly outside a side plane (by its bounding sphere), or not finite (the simulation reports
// non-finite states itself; they must not paint the screen).
std::optional<CameraBox> view_box(const CameraPose& cam, const FragmentState& f) {
  const CameraBox b = camera_box(cam, f);
  if (!b.finite()) return std::nullopt;
  if (!cam.frustum().sphere_may_show(b.centre_m, f.half_extents_m.norm())) return std::nullopt;
  return b;
}

// A convex piece seen from `cam`, its camera-space vertices in `out`, or false when it cannot show
// (the same tests as view_box, with the hull's own bounding sphere).
bool view_hull(const CameraPose& cam, const FragmentState& f, std::vector<Eigen::Vector3d>& out) {
  hull_camera_vertices(cam, f, out);
  for (const Eigen::Vector3d& v : out) {
    if (!v.allFinite()) return false;
  }
  return cam.frustum().sphere_may_show(cam.to_camera(f.position_m), f.shape->radius_m);
}

// Whether face `i` of the piece faces the eye at the origin, i.e. the eye is outside its plane
// (n . x = d in the body frame, n_c . x = n_c . c + d in camera space). Testing the plane rather
// than a vertex gives every face of a thin piece one answer however its vertices round.
bool hull_face_faces_eye(const Eigen::Matrix3d& body_to_cam, const Eigen::Vector3d& centre_m,
                         const ConvexShape& shape, std::size_t i) {
  return (body_to_cam * shape.normals[i]).dot(centre_m) + shape.offsets_m[i] < 0.0;
}

// Appends to pts where the piece's edges (camera-space vertices v) cross z = near_m, projected.
void hull_cut_points(const Rasterizer& r, const ConvexShape& shape,
                     const std::vector<Eigen::Vector3d>& v, double near_m,
                     std::vector<ScreenPoint>& pts) {
  for (const std::vector<int>& face : shape.faces) {
    for (std::size_t k = 0; k < face.size(); ++k) {
      const int ia = face[k];
      const int ib = face[k + 1 == face.size() ? 0 : k + 1];
      if (ia > ib) continue;  // each edge borders two faces, once each way, so take it once
      const Eigen::Vector3d& a = v[static_cast<std::size_t>(ia)];
      const Eigen::Vector3d& b = v[static_cast<std::size_t>(ib)];
      if ((a.z() >= near_m) == (b.z() >= near_m)) continue;
      const double t = (near_m - a.z()) / (b.z() - a.z());
      Eigen::Vector3d p = a + t * (b - a);
      p.z() = near_m;
      pts.push_back(r.project(p));
    }
  }
}

// The convex section's points in angular order around their mean, outlined.
void draw_section(Image& image, ScreenPoint* pts, int n, int thickness_px) {
  if (n < 3) return;
  ScreenPoint mid;
  for (int i = 0; i < n; ++i) {
    mid.x += pts[i].x / n;
    mid.y += pts[i].y / n;
  }
  std::sort(pts, pts + n, [&](const ScreenPoint& a, const ScreenPoint& b) {
    return std::atan2(a.y - mid.y, a.x - mid.x) < std::atan2(b.y - mid.y, b.x - mid.x);
  });
  for (int i = 0; i < n; ++i) draw_line(image, pts[i], pts[(i + 1) % n], kCutColour, thickness_px);
}

}  // namespace

void FrameRenderer::draw_hull_faces(int index, const FragmentState& f) {
  const CameraPose& cam = raster_.camera();
  if (!view_hull(cam, f, hull_vertices_)) return;
  const ConvexShape& shape = *f.shape;
  const Eigen::Matrix3d m = body_to_camera(cam, f.rotation);
  const Eigen::Vector3d c = cam.to_camera(f.position_m);
  const Rgb base = fragment_colour(index);
  for (std::size_t i = 0; i < shape.faces.size(); ++i) {
    const std::vector<int>& face = shape.faces[i];
    if (face.size() < 3 || !hull_face_faces_eye(m, c, shape, i)) continue;  // back faces culled
    const Rgb shade = shaded_colour(base, f.rotation * shape.normals[i]);
    const Eigen::Vector3d& p0 = hull_vertices_[static_cast<std::size_t>(face[0])];
    for (std::size_t k = 1; k + 1 < face.size(); ++k) {  // a fan, as the face is convex
      raster_.fill_triangle(p0, hull_vertices_[static_cast<std::size_t>(face[k])],
                            hull_vertices_[static_cast<std::size_t>(face[k + 1])], shade);
    }
  }
}

void FrameRenderer::draw_hull_outline(const FragmentState& f) {
  const CameraPose& cam = raster_.camera();
  if (!view_hull(cam, f, hull_vertices_)) return;
  const ConvexShape& shape = *f.shape;
  const Eigen::Matrix3d m = body_to_camera(cam, f.rotation);
  const Eigen::Vector3d c = cam.to_camera(f.position_m);
  // The edges of the visible faces; an edge two visible faces share is drawn twice, to the same
  // pixels.
  for (std::size_t i = 0; i < shape.faces.size(); ++i) {
    if (!hull_face_faces_eye(m, c, shape, i)) continue;
    const std::vector<int>& face = shape.faces[i];
    for (std::size_t k = 0; k < face.size(); ++k) {
      raster_.draw_segment(hull_vertices_[static_cast<std::size_t>(face[k])],
                           hull_vertices_[static_cast<std::size_t>(face[(k + 1) % face.size()])],
                           kCandidateColour, line_px_);
    }
  }
}

void FrameRenderer::draw_hull_cut(Image& image, const FragmentState& f) {
  const CameraPose& cam = raster_.camera();
  if (!view_hull(cam, f, hull_vertices_)) return;
  hull_cut_points_.clear();
  hull_cut_points(raster_, *f.shape, hull_vertices_, cam.near_m, hull_cut_points_);
  draw_section(image, hull_cut_points_.data(), static_cast<int>(hull_cut_points_.size()),
               2 * line_px_);
}

void FrameRenderer::draw_faces(int index, const FragmentState& f) {
  if (f.shape) {
    draw_hull_faces(index, f);
    return;
  }
  const std::optional<CameraBox> box = view_box(raster_.camera(), f);
  if (!box) return;
  const Rgb base = fragment_colour(index);
  for (int k = 0; k < 3; ++k) {
    const int u = (k + 1) % 3;
    const int v = (k + 2) % 3;
    for (const double s : {-1.0, 1.0}) {
      if (!faces_eye(*box, k, s)) continue;  // back faces are culled
      const Rgb shade = shaded_colour(base, s * f.rotation.col(k));
      const Eigen::Matrix3d& axes = box->half_axes_m;
      const Eigen::Vector3d fc = box->centre_m + s * axes.col(k);
      const Eigen::Vector3d p0 = fc - axes.col(u) - axes.col(v);
      const Eigen::Vector3d p1 = fc + axes.col(u) - axes.col(v);
      const Eigen::Vector3d p2 = fc + axes.col(u) + axes.col(v);
      const Eigen::Vector3d p3 = fc - axes.col(u) + axes.col(v);
      raster_.fill_triangle(p0, p1, p2, shade);
      raster_.fill_triangle(p0, p2, p3, shade);
    }
  }
}

void FrameRenderer::draw_outline(const FragmentState& f) {
  if (f.shape) {
    draw_hull_outline(f);
    return;
  }
  const std::optional<CameraBox> box = view_box(raster_.camera(), f);
  if (!box) return;
  // The edges of the visible faces. The edge along axis k from corner i is where the faces across
  // axes u and v (on i's sides) meet, and it shows when either faces the eye.
  for (int i = 0; i < 8; ++i) {
    for (int k = 0; k < 3; ++k) {
      if ((i >> k) & 1) continue;  // each edge once, from its corner with bit k clear
      const int u = (k + 1) % 3;
      const int v = (k + 2) % 3;
      if (faces_eye(*box, u, (i >> u) & 1 ? 1.0 : -1.0) ||
          faces_eye(*box, v, (i >> v) & 1 ? 1.0 : -1.0)) {
        raster_.draw_segment(box->corner(i), box->corner(i | (1 << k)), kCandidateColour, line_px_);
      }
    }
  }
}

void FrameRenderer::draw_cut(Image& image, const FragmentState& f) {
  if (f.shape) {
    draw_hull_cut(image, f);
    return;
  }
  const CameraPose& cam = raster_.camera();
  const std::optional<CameraBox> box = view_box(cam, f);
  if (!box) return;
  // The near plane's section through the box is where its 12 edges cross z = near, in angular
  // order around their mean (the section is convex).
  const std::array<Eigen::Vector3d, 8> corner = box->corners();
  std::array<ScreenPoint, 12> pts;
  int n = 0;
  for (int i = 0; i < 8; ++i) {
    for (int k = 0; k < 3; ++k) {
      const int j = i | (1 << k);
      if (j == i) continue;
      const Eigen::Vector3d& a = corner[i];
      const Eigen::Vector3d& b = corner[j];
      if ((a.z() >= cam.near_m) == (b.z() >= cam.near_m)) continue;
      const double t = (cam.near_m - a.z()) / (b.z() - a.z());
      Eigen::Vector3d p = a + t * (b - a);
      p.z() = cam.near_m;
      pts[n++] = raster_.project(p);
    }
  }
  draw_section(image, pts.data(), n, 2 * line_px_);
}

void FrameRenderer::draw_force(Image& image, const FragmentState& f, const Eigen::Vector3d& force) {
  if (!(f.mass_kg > 0.0)) return;
  const CameraPose& cam = raster_.camera();
  const Eigen::Vector3d from = cam.to_camera(f.position_m);
  const Eigen::Vector3d to =
      cam.to_camera(f.position_m + force / f.mass_kg * style_.arrow_m_per_mps2);
  ScreenPoint a;
  ScreenPoint b;
  if (!raster_.draw_segment(from, to, kForceColour, line_px_, &a, &b)) return;
  // The head, in screen space, where the clipped shaft ends (if its tip is the arrow's own tip).
  if (to.z() < cam.near_m || to.z() > cam.far_m) return;
  const double dx = b.x - a.x;
  const double dy = b.y - a.y;
  const double len = std::hypot(dx, dy);
  if (!(len > 1.0)) return;
  const double head = std::min(0.4 * len, 6.0 * line_px_);
  const double ux = dx / len;
  const double uy = dy / len;
  constexpr double kCos = 0.866;  // 30 degrees either side of the shaft
  constexpr double kSin = 0.5;
  draw_line(image, b, {b.x - head * (kCos * ux - kSin * uy), b.y - head * (kSin * ux + kCos * uy)},
            kForceColour, line_px_);
  draw_line(image, b, {b.x - head * (kCos * ux + kSin * uy), b.y - head * (-kSin * ux + kCos * uy)},
            kForceColour, line_px_);
}

Image FrameRenderer::render(const StepSnapshot& snap) {
  Image image(style_.width_px, style_.height_px);
  raster_.begin(image, snap.camera);
  draw_background(image, snap.camera);
  // A faded fragment (fade) is drawn dithered by its opacity; an invisible one not at all.
  const auto opacity = [&snap](std::size_t i) {
    return snap.opacity.empty() ? 1.0f : snap.opacity[i];
  };
  for (std::size_t i = 0; i < snap.fragments.size(); ++i) {
    const float alpha = opacity(i);
    if (!(alpha > 0.0f)) continue;
    raster_.set_opacity(alpha);
    draw_faces(static_cast<int>(i), snap.fragments[i]);
  }
  raster_.set_opacity(1.0f);
  // Overlays, over every fragment.
  const FrameOverlays& o = style_.overlays;
  const int count = static_cast<int>(snap.fragments.size());
  if (o.cuts) {
    // Only what is drawn can show a cut.
    for (std::size_t i = 0; i < snap.fragments.size(); ++i) {
      if (opacity(i) > 0.0f) draw_cut(image, snap.fragments[i]);
    }
  }
  if (o.candidates) {
    for (const int i : snap.candidates) {
      if (i >= 0 && i < count) draw_outline(snap.fragments[static_cast<std::size_t>(i)]);
    }
  }
  if (o.forces) {
    for (const AppliedForce& a : snap.forces) {
      if (a.fragment >= 0 && a.fragment < count) {
        draw_force(image, snap.fragments[static_cast<std::size_t>(a.fragment)], a.force_N);
      }
    }
  }
  if (o.central) {
    // The occlusion metric's central region, this share of the width and height, centred.
    const auto margin = [this](int n) {
      return static_cast<int>(std::lround(0.5 * n * (1.0 - central_share_)));
    };
    const int mx = margin(image.width());
    const int my = margin(image.height());
    draw_rect_outline(image, mx, my, image.width() - mx, image.height() - my, kCentralColour,
                      line_px_);
  }
  return image;
}

}  // namespace fragsim
