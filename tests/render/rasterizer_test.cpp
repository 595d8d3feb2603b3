// The software rasteriser on the square camera of render_fixtures.hpp: clipping at the near plane,
// which pixels a triangle covers, a segment clipped at the plane, and the ordered dither.

#include "render/rasterizer.hpp"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <array>

#include "render/image.hpp"
#include "render/render_fixtures.hpp"

namespace fragsim {
namespace {

using test::kSize;
using test::square_camera;

TEST(Rasterizer, ClipsAPolygonAtThePlaneExactly) {
  const std::array<Eigen::Vector3d, 3> tri{Eigen::Vector3d(0, 0, 0.05), Eigen::Vector3d(1, 0, 1.0),
                                           Eigen::Vector3d(0, 1, 1.0)};
  std::array<Eigen::Vector3d, 4> out;
  const int n = clip_polygon_z(tri.data(), 3, 0.1, true, out.data());
  ASSERT_EQ(n, 4);  // the corner in front of the plane becomes two points on it
  int on_plane = 0;
  for (int i = 0; i < n; ++i) {
    EXPECT_GE(out[i].z(), 0.1);
    on_plane += out[i].z() == 0.1;
  }
  EXPECT_EQ(on_plane, 2);
  // The cut point on edge (0, 0, 0.05) -> (1, 0, 1): x = (0.1 - 0.05) / 0.95.
  EXPECT_NEAR(out[0].x(), 0.05 / 0.95, 1e-15);
  EXPECT_EQ(clip_polygon_z(tri.data(), 3, 2.0, true, out.data()), 0);   // all in front
  EXPECT_EQ(clip_polygon_z(tri.data(), 3, 0.01, true, out.data()), 3);  // all behind
}

TEST(Rasterizer, TriangleCoversThePixelsWhoseCentresItContains) {
  Image img(kSize, kSize);
  Rasterizer r;
  r.begin(img, square_camera());
  const Rgb red{255, 0, 0};
  // At depth 2, camera-space (0, 0) to (1, 0) to (0, 1) spans columns 100..150, rows 50..100.
  r.fill_triangle({0, 0, 2}, {1, 0, 2}, {0, 1, 2}, red);
  EXPECT_EQ(img.at(101, 98), red);
  EXPECT_EQ(img.at(140, 98), red);
  EXPECT_EQ(img.at(101, 52), red);
  EXPECT_EQ(img.at(99, 98), Rgb{});    // left of x = 0
  EXPECT_EQ(img.at(101, 101), Rgb{});  // below y = 0
  EXPECT_EQ(img.at(140, 60), Rgb{});   // beyond the hypotenuse
  EXPECT_FLOAT_EQ(r.inverse_depth(110, 90), 0.5f);
  EXPECT_EQ(r.inverse_depth(10, 10), 0.0f);
}

TEST(Rasterizer, SegmentIsClippedAtTheNearPlane) {
  Image img(kSize, kSize);
  Rasterizer r;
  r.begin(img, square_camera());
  ScreenPoint a;
  ScreenPoint b;
  // From depth 0.05 (in front of the near plane) to depth 1 along x = 0.05: the drawn part starts
  // on the plane, at x / z = 0.5 (column 150), and ends at x / z = 0.05 (column 105).
  ASSERT_TRUE(r.draw_segment({0.05, 0, 0.05}, {0.05, 0, 1.0}, {255, 255, 255}, 1, &a, &b));
  EXPECT_NEAR(a.x, 150.0, 1e-9);
  EXPECT_NEAR(b.x, 105.0, 1e-9);
  EXPECT_EQ(img.at(160, 100), Rgb{});  // the part in front of the plane would reach column 200
  EXPECT_FALSE(r.draw_segment({0, 0, 0.01}, {1, 0, 0.05}, {255, 255, 255}));
}

TEST(Rasterizer, OrderedDitherShowsTheOpacitysShareOfEachFourByFourBlock) {
  // 16 thresholds (b + 0.5) / 16: an opacity of k / 16 shows exactly k pixels of every block.
  for (int k = 0; k <= 16; ++k) {
    int shown = 0;
    for (int row = 0; row < 4; ++row) {
      for (int col = 0; col < 4; ++col) shown += dither_shows(col + 8, row + 12, k / 16.0f);
    }
    EXPECT_EQ(shown, k) << k;
  }
  // Half: a checkerboard in each 2 x 2 (neighbours differ), so it reads as see-through.
  EXPECT_NE(dither_shows(0, 0, 0.5f), dither_shows(1, 0, 0.5f));
  EXPECT_NE(dither_shows(0, 0, 0.5f), dither_shows(0, 1, 0.5f));
}

}  // namespace
}  // namespace fragsim
