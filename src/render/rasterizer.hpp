#pragma once
// A software rasteriser in a GPU's manner, for one camera pose at a time. Geometry is given in
// camera coordinates (CameraPose::to_camera, x right, y up, z = depth along the view direction).
// Each triangle is clipped against the near and far planes of that pose (Sutherland-Hodgman on
// z = near_m and z = far_m), then divided by its depth and filled into the image with a z-buffer,
// so a box crossing the near plane loses the part in front of it, and with back faces culled by
// the caller its inside is not drawn (the hole a game shows). Lines are clipped the same way and
// drawn over everything, without a depth test (overlays).
//
// The frustum's [-1, 1]^2 in NDC maps onto the whole image, x to the right and y DOWN (row 0 is the
// top), as in OcclusionMetric; pixel (col, row) spans [col, col + 1] x [row, row + 1] and is drawn
// when its centre lies in a triangle (edges included).

#include <Eigen/Core>
#include <cassert>
#include <cstddef>
#include <vector>

#include "control/geometry/camera_pose.hpp"
#include "control/geometry/frustum.hpp"
#include "render/image.hpp"

namespace fragsim {

// Sutherland-Hodgman against one plane z = plane_z keeps the part of the convex polygon
// in[0..n) with z >= plane_z (keep_greater) or z <= plane_z, in order; points made on the plane
// get z = plane_z exactly. Writes to out (room for n + 1 points) and returns the count (0 when
// nothing is kept).
int clip_polygon_z(const Eigen::Vector3d* in, int n, double plane_z, bool keep_greater,
                   Eigen::Vector3d* out);

class Rasterizer {
 public:
  // Starts a frame in `image` (its size is the viewport) seen from `camera` and clears the depth
  // buffer to "infinitely far". The image's pixels are left as they are.
  void begin(Image& image, const CameraPose& camera);

  const CameraPose& camera() const { return camera_; }
  int width() const { return width_; }
  int height() const { return height_; }

  // The frame's perspective divide and viewport.
  const PixelProjection& projection() const { return projection_; }
  // A camera-space point with z > 0 on the screen.
  ScreenPoint project(const Eigen::Vector3d& p) const { return projection_.project(p); }
  // The camera-space direction (x / z, y / z, 1) through the centre of pixel (col, row).
  Eigen::Vector3d pixel_direction(int col, int row) const {
    return projection_.pixel_direction(col, row);
  }

  // The opacity the next triangles are drawn with, in [0, 1]. Below 1 a triangle is drawn
  // dithered, as Unreal's and Godot's distance fades are, through a 4x4 ordered (Bayer) matrix
  // fixed to the screen. A pixel is written (colour and depth, as an opaque one) only where the
  // opacity exceeds its threshold (b + 0.5) / 16, b the matrix's entry 0..15, so a share of
  // about `opacity` of the pixels shows and the rest show what lies behind. 1 (the default)
  // draws every pixel.
  void set_opacity(float opacity) { opacity_ = opacity; }
  float opacity() const { return opacity_; }

  // Clips the camera-space triangle at the near and far planes and fills what is left, each
  // pixel only where it is nearer than what the depth buffer holds. Both windings are drawn.
  void fill_triangle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c,
                     Rgb colour);
  // Writes one pixel if 1 / depth `inverse_depth` is nearer than the buffer's (for surfaces the
  // caller computes per pixel, such as the ground).
  void write_if_nearer(int col, int row, float inverse_depth, Rgb colour) {
    assert(image_ && image_->contains(col, row));
    float& d = inverse_depth_[static_cast<std::size_t>(row) * static_cast<std::size_t>(width_) +
                              static_cast<std::size_t>(col)];
    if (inverse_depth > d) {
      d = inverse_depth;
      image_->set(col, row, colour);
    }
  }
  // 1 / depth of what pixel (col, row) shows; 0 where nothing was drawn.
  float inverse_depth(int col, int row) const {
    return inverse_depth_[static_cast<std::size_t>(row) * static_cast<std::size_t>(width_) +
                          static_cast<std::size_t>(col)];
  }

  // A camera-space segment clipped at the near and far planes, projected and drawn over the image
  // with a square pen `thickness_px` wide. Returns false if nothing of it is in front of the near
  // plane; then the projected ends are not set.
  bool draw_segment(const Eigen::Vector3d& a, const Eigen::Vector3d& b, Rgb colour,
                    int thickness_px = 1, ScreenPoint* a_px = nullptr, ScreenPoint* b_px = nullptr);

 private:
  void fill_projected(const ScreenPoint* p, const double* inv_z, Rgb colour);

  Image* image_ = nullptr;
  CameraPose camera_;
  int width_ = 0;
  int height_ = 0;
  PixelProjection projection_;
  std::vector<float> inverse_depth_;  // reused from frame to frame
  float opacity_ = 1.0f;
};

// Whether the ordered dither draws pixel (col, row) of a surface of opacity `opacity`.
bool dither_shows(int col, int row, float opacity);

// A 2-D line from a to b (pixel coordinates, clipped to the image) with a square pen.
void draw_line(Image& image, ScreenPoint a, ScreenPoint b, Rgb colour, int thickness_px = 1);
// The outline of columns [x0, x1) and rows [y0, y1), `thickness_px` wide, inside the rectangle.
void draw_rect_outline(Image& image, int x0, int y0, int x1, int y1, Rgb colour,
                       int thickness_px = 1);

}  // namespace fragsim
