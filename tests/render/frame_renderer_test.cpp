// Frames on hand-worked boxes and convex pieces in front of the square camera of
// render_fixtures.hpp (a point at depth z and lateral offset x lands on column 100 + 100 x / z,
// row 100 - 100 y / z): silhouettes, shading, depth order, the near plane's cut, the ground and
// sky, the overlays, faded fragments, and the same bytes for the same snapshot.

#include "render/frame_renderer.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <limits>
#include <vector>

#include "render/image.hpp"
#include "render/render_fixtures.hpp"
#include "support/convex_shapes.hpp"
#include "support/test_scenes.hpp"

namespace fragsim {
namespace {

using test::kSize;
using test::render;
using test::sky_scene;
using test::snapshot;
using test::square_camera;
using test::square_style;

// An axis-aligned box given by its camera-space extents (depth = -world z).
FragmentState box(double x0, double x1, double y0, double y1, double depth0, double depth1) {
  FragmentState f;
  f.position_m = {0.5 * (x0 + x1), 0.5 * (y0 + y1), -0.5 * (depth0 + depth1)};
  f.half_extents_m = {0.5 * (x1 - x0), 0.5 * (y1 - y0), 0.5 * (depth1 - depth0)};
  f.radius_m = f.half_extents_m.norm();
  f.mass_kg = 1.0;
  return f;
}

// Which pixels differ from the same view without fragments.
std::vector<std::vector<bool>> drawn(const Image& img, const CameraPose& cam = square_camera()) {
  const Image empty = render({}, cam);
  std::vector<std::vector<bool>> d(img.height(), std::vector<bool>(img.width()));
  for (int y = 0; y < img.height(); ++y) {
    for (int x = 0; x < img.width(); ++x) d[y][x] = !(img.at(x, y) == empty.at(x, y));
  }
  return d;
}

const Eigen::Vector3d kTowardCamera{0.0, 0.0, 1.0};  // the outward normal of a box's near face

TEST(FrameRenderer, SquareFacingTheCameraCoversThePredictedRectangle) {
  // A 1 m square plate (1 mm thick) at depth 5, its centre at (0.3, 0.2): its near face at depth
  // 4.9995 spans columns 100 + 100 (-0.2 .. 0.8) / 4.9995 and rows 100 - 100 (0.7 .. -0.3)
  // / 4.9995.
  const FragmentState plate = box(-0.2, 0.8, -0.3, 0.7, 4.9995, 5.0005);
  const auto d = drawn(render({plate}));
  const double z = 4.9995;
  const double x0 = 100 - 100 * 0.2 / z;
  const double x1 = 100 + 100 * 0.8 / z;
  const double y0 = 100 - 100 * 0.7 / z;
  const double y1 = 100 + 100 * 0.3 / z;
  int inside = 0;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const double cx = x + 0.5;
      const double cy = y + 0.5;
      if (cx > x0 + 1 && cx < x1 - 1 && cy > y0 + 1 && cy < y1 - 1) {
        EXPECT_TRUE(d[y][x]) << x << "," << y;
        ++inside;
      } else if (cx < x0 - 1 || cx > x1 + 1 || cy < y0 - 1 || cy > y1 + 1) {
        EXPECT_FALSE(d[y][x]) << x << "," << y;
      }
    }
  }
  EXPECT_GT(inside, 300);
}

// A convex piece's silhouette against the pixel-space convex polygon poly (counter-clockwise or
// clockwise): pixels whose centre is more than 1 px inside are drawn, more than 1 px outside are
// not, and the count is the polygon's area within its boundary's pixels (its perimeter).
void expect_silhouette(const std::vector<std::vector<bool>>& d,
                       const std::vector<Eigen::Vector2d>& poly) {
  double area2 = 0.0;
  double perimeter = 0.0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Eigen::Vector2d& a = poly[i];
    const Eigen::Vector2d& b = poly[(i + 1) % poly.size()];
    area2 += a.x() * b.y() - a.y() * b.x();
    perimeter += (b - a).norm();
  }
  const double sign = area2 > 0.0 ? 1.0 : -1.0;
  int count = 0;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      const Eigen::Vector2d p(x + 0.5, y + 0.5);
      double inside_by = std::numeric_limits<double>::infinity();  // distance to the nearest edge
      for (std::size_t i = 0; i < poly.size(); ++i) {
        const Eigen::Vector2d e = poly[(i + 1) % poly.size()] - poly[i];
        const Eigen::Vector2d q = p - poly[i];
        inside_by = std::min(inside_by, sign * (e.x() * q.y() - e.y() * q.x()) / e.norm());
      }
      if (inside_by > 1.0) {
        EXPECT_TRUE(d[y][x]) << x << "," << y;
      } else if (inside_by < -1.0) {
        EXPECT_FALSE(d[y][x]) << x << "," << y;
      }
      count += d[y][x];
    }
  }
  EXPECT_NEAR(count, 0.5 * std::abs(area2), perimeter);
  EXPECT_GT(count, 300);
}

// Pixel coordinates of a camera-space point on the 200-pixel square frame.
Eigen::Vector2d pixel(double x, double y, double depth) {
  return {100.0 + 100.0 * x / depth, 100.0 - 100.0 * y / depth};
}

TEST(FrameRenderer, TetrahedronFaceOnShowsItsProjectedTriangle) {
  // A regular tetrahedron of circumradius R = 1.5 m at depth 5, a face toward the camera (vertex
  // 0 turned away, along -z): the face lies at depth 5 - R / 3 = 4.5, its vertices on a circle of
  // radius 2 sqrt(2) R / 3 = sqrt(2) about the view axis, and the far vertex projects inside it,
  // so the silhouette is that face's triangle.
  const double a = 1.5 / std::sqrt(3.0);
  const ConvexShape t = test::regular_tetrahedron(a);
  const Eigen::Matrix3d rot =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::Ones(), -Eigen::Vector3d::UnitZ())
          .toRotationMatrix();
  const FragmentState f = test::shaped_fragment(t, {0.0, 0.0, -5.0}, rot);
  const Image img = render({f});
  std::vector<Eigen::Vector2d> tri;
  for (const int i : t.faces[0]) {  // the face across from vertex 0
    const Eigen::Vector3d w = f.position_m + rot * t.vertices_m[static_cast<std::size_t>(i)];
    EXPECT_NEAR(-w.z(), 4.5, 1e-12);
    EXPECT_NEAR(std::hypot(w.x(), w.y()), std::sqrt(2.0), 1e-12);
    tri.push_back(pixel(w.x(), w.y(), -w.z()));
  }
  expect_silhouette(drawn(img), tri);
  // It is one face, lit as a box face with that normal is (toward the camera).
  EXPECT_EQ(img.at(100, 100), shaded_colour(fragment_colour(0), kTowardCamera));
}

TEST(FrameRenderer, TetrahedronEdgeOnShowsAQuadrilateral) {
  // Unturned, the tetrahedron of half cube side a = 1 at depth 5 shows two edges: the one from
  // (1, 1) to (-1, -1) at depth 4 and the one from (1, -1) to (-1, 1) at depth 6. Its silhouette is
  // the kite with half diagonals 1 / 4 and 1 / 6 (x / z) along the two diagonals.
  const ConvexShape t = test::regular_tetrahedron(1.0);
  const FragmentState f = test::shaped_fragment(t, {0.0, 0.0, -5.0});
  const std::vector<Eigen::Vector2d> kite{pixel(1.0, 1.0, 4.0), pixel(1.0, -1.0, 6.0),
                                          pixel(-1.0, -1.0, 4.0), pixel(-1.0, 1.0, 6.0)};
  expect_silhouette(drawn(render({f})), kite);
}

TEST(FrameRenderer, CubeHullDrawsAsItsBox) {
  // The same turned cube as a box and as a hull: the same faces, shades and depths, so the same
  // pixels but for a pixel centre within rounding of an edge (at most 1% of the ~1400 drawn).
  const ConvexShape cube = test::box_hull(Eigen::Vector3d::Constant(0.6));
  const Eigen::Matrix3d rot =
      Eigen::Quaterniond(Eigen::AngleAxisd(0.5, Eigen::Vector3d(1.0, 2.0, 0.5).normalized()))
          .toRotationMatrix();
  const FragmentState hull = test::shaped_fragment(cube, {0.2, -0.1, -4.0}, rot);
  const Image a = render({hull});
  const Image b = render({test::as_box(hull)});
  int differ = 0;
  int drawn_px = 0;
  const auto d = drawn(b);
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      differ += !(a.at(x, y) == b.at(x, y));
      drawn_px += d[y][x];
    }
  }
  EXPECT_GT(drawn_px, 1000);
  EXPECT_LE(differ, drawn_px / 100);
}

TEST(FrameRenderer, TetrahedronCrossingTheNearPlaneShowsItsCut) {
  // Vertex first through a near plane at 4.5 m: the plane cuts the three edges from vertex 0
  // (toward the camera, at depth 5 - R = 3.5) to the far face (at 5 + R / 3 = 5.5).
  const double a = 1.5 / std::sqrt(3.0);
  const ConvexShape t = test::regular_tetrahedron(a);
  const Eigen::Matrix3d rot =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::Ones(), Eigen::Vector3d::UnitZ())
          .toRotationMatrix();
  const FragmentState f = test::shaped_fragment(t, {0.0, 0.0, -5.0}, rot);
  FrameStyle style = square_style();
  style.overlays.cuts = true;
  const Image img = render({f}, square_camera(4.5), sky_scene(), style);
  int cut_px = 0;
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) cut_px += img.at(x, y) == kCutColour;
  }
  // The section is a triangle of circumradius 2 sqrt(2) R / 3 * (1 / 2) (half way from the vertex
  // to the far face) = 0.707 m at depth 4.5: perimeter 3 sqrt(3) 0.707 / 4.5 * 100 = 82 px, drawn
  // 2 px wide.
  EXPECT_GT(cut_px, 82);
  EXPECT_LT(cut_px, 4 * 82);
  // Without the overlay the cut is a hole: the eye sees into the piece where its front is gone,
  // and back faces are culled, so the pixel on the view axis shows the sky.
  const Image plain = render({f}, square_camera(4.5));
  EXPECT_EQ(plain.at(100, 100), render({}, square_camera(4.5)).at(100, 100));
}

TEST(FrameRenderer, RightIsScreenRightAndUpIsScreenTop) {
  // A camera looking down +x: its right is +z, its up +y.
  CameraPose cam = square_camera();
  cam.forward = {1, 0, 0};
  cam.right = {0, 0, 1};
  cam.up = {0, 1, 0};
  FragmentState f;
  f.half_extents_m = {0.1, 0.1, 0.1};
  f.position_m = {3, 0, 1};  // to the camera's right
  auto d = drawn(render({f}, cam), cam);
  EXPECT_TRUE(d[100][100 + static_cast<int>(100.0 / 3.0)]);
  EXPECT_FALSE(d[100][100 - static_cast<int>(100.0 / 3.0)]);
  f.position_m = {3, 1, 0};  // above the view axis
  d = drawn(render({f}, cam), cam);
  EXPECT_TRUE(d[100 - static_cast<int>(100.0 / 3.0)][100]);
  EXPECT_FALSE(d[100 + static_cast<int>(100.0 / 3.0)][100]);
}

TEST(FrameRenderer, FacesAreShadedByTheirWorldNormal) {
  // A cube below and left of the view axis shows its near face, its top and its right side.
  FragmentState f = box(-1.0, -0.6, -1.0, -0.6, 2.0, 2.4);
  const Image img = render({f});
  const Rgb base = fragment_colour(0);
  // Near face (depth 2): columns 50..70, rows 130..150.
  EXPECT_EQ(img.at(60, 140), shaded_colour(base, kTowardCamera));
  // Top (y = -0.6, depths 2..2.4): rows 100 + 100 * 0.6 / z = 125..130; column 100 - 80 / 2.2.
  EXPECT_EQ(img.at(64, 127), shaded_colour(base, {0, 1, 0}));
  // Right side (x = -0.6, depths 2..2.4): columns 100 - 60 / z = 70..75.
  EXPECT_EQ(img.at(72, 136), shaded_colour(base, {1, 0, 0}));
  // The light comes from above: a top is brighter than a near face, a near face than a right side.
  const auto sum = [](Rgb c) { return c.r + c.g + c.b; };
  EXPECT_GT(sum(shaded_colour(base, {0, 1, 0})), sum(shaded_colour(base, kTowardCamera)));
  EXPECT_GT(sum(shaded_colour(base, kTowardCamera)), sum(shaded_colour(base, {1, 0, 0})));
  EXPECT_EQ(shaded_colour(base, {0, -1, 0}), shaded_colour(base, {1, 0, 0}));  // both unlit
}

TEST(FrameRenderer, NearerOfTwoOverlappingBoxesWinsWhateverTheOrder) {
  const FragmentState near = box(-0.5, 0.5, -0.5, 0.5, 3.0, 3.2);
  const FragmentState far = box(-0.2, 1.0, -0.2, 1.0, 5.0, 5.2);
  // Fragment 0 drawn first, then 1: the colour at the centre is the near box's, whichever it is.
  Image img = render({far, near});
  EXPECT_EQ(img.at(100, 100), shaded_colour(fragment_colour(1), kTowardCamera));
  img = render({near, far});
  EXPECT_EQ(img.at(100, 100), shaded_colour(fragment_colour(0), kTowardCamera));
  // Where only the far box shows (x / z = 0.15 at depth 5 lies beyond the near box's 0.5 / 3).
  EXPECT_EQ(img.at(100 + 17, 100 - 17), shaded_colour(fragment_colour(1), kTowardCamera));
}

TEST(FrameRenderer, BoxCrossingTheNearPlaneIsCutOpen) {
  // Depths 0.05 .. 0.5 across the near plane at 0.1, x in [0.02, 0.06], y in [-0.1, 0.1].
  // - In front of the plane (not drawn): x / z up to 0.06 / 0.05 = 1.2, beyond what the part
  //   behind reaches (0.06 / 0.1 = 0.6): column 170 (x / z = 0.7).
  // - The cut (z = 0.1, x / z in [0.2, 0.6]): the hole, the box's inside is not drawn: column 140.
  // - Behind the plane: its side x = 0.02 faces the eye, at x / z in [0.04, 0.2]: column 110.
  const FragmentState f = box(0.02, 0.06, -0.1, 0.1, 0.05, 0.5);
  const auto d = drawn(render({f}));
  EXPECT_FALSE(d[100][170]);
  EXPECT_FALSE(d[100][140]);
  EXPECT_TRUE(d[100][110]);
  EXPECT_TRUE(d[100][105]);
  // The same box with the near plane at 1 cm is whole: its near face covers column 170.
  const CameraPose close = square_camera(0.01);
  EXPECT_TRUE(drawn(render({f}, close), close)[100][170]);
  // The cut overlay outlines the section: its left edge is column 120 (x / z = 0.2).
  FrameStyle style = square_style();
  style.overlays.cuts = true;
  const Image cut = render({f}, square_camera(), sky_scene(), style);
  EXPECT_TRUE(cut.at(119, 100) == kCutColour || cut.at(120, 100) == kCutColour);
  EXPECT_FALSE(cut.at(140, 100) == kCutColour);
}

TEST(FrameRenderer, BoxWhollyInFrontOfTheNearPlaneOrBehindTheEyeIsNotDrawn) {
  const auto d1 = drawn(render({box(-0.01, 0.01, -0.01, 0.01, 0.02, 0.05)}));
  const auto d2 = drawn(render({box(-1, 1, -1, 1, -3, -2)}));
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      ASSERT_FALSE(d1[y][x] || d2[y][x]) << x << "," << y;
    }
  }
}

TEST(FrameRenderer, NonFiniteFragmentIsSkipped) {
  FragmentState f = box(-0.5, 0.5, -0.5, 0.5, 3, 3.2);
  f.position_m.x() = std::nan("");
  const Image img = render({f});
  EXPECT_EQ(img.bytes(), render({}).bytes());
}

TEST(FrameRenderer, GroundBelowTheHorizonSkyAbove) {
  Scene scene;  // ground at y = 0
  CameraPose cam = square_camera();
  cam.eye_m = {0.0, 1.6, 0.0};
  const Image img = render({}, cam, scene);
  const Rgb top = img.at(100, 5);
  const Rgb bottom = img.at(100, 195);
  EXPECT_GT(top.b, top.r + 40);                  // blue sky
  EXPECT_LT(std::abs(bottom.r - bottom.b), 30);  // grey ground
  // The horizon of a level camera is the middle row: just above it is sky, just below it ground
  // (hazed toward the sky's horizon colour, but not blue).
  EXPECT_GT(img.at(100, 98).b, img.at(100, 98).r + 20);
  EXPECT_LT(img.at(100, 103).b, img.at(100, 103).r + 20);
  // A box sunk halfway into the ground (world y -1 .. 1, near face at depth 4): above the ground
  // its near face shows (world y 0.5: row 100 + 100 * 1.1 / 4 = 127.5), below it the ground hides
  // it (world y -0.5, row 152.5, where the ground lies at depth 1.6 / 0.525 = 3.05).
  FragmentState sunk = box(-0.5, 0.5, -1.0, 1.0, 4.0, 5.0);
  const Image with_box = render({sunk}, cam, scene);
  const Rgb face = shaded_colour(fragment_colour(0), kTowardCamera);
  EXPECT_EQ(with_box.at(100, 127), face);
  EXPECT_FALSE(with_box.at(100, 152) == face);
  EXPECT_EQ(with_box.at(100, 152), img.at(100, 152));
}

TEST(FrameRenderer, CandidatesAndForcesOverlays) {
  FragmentState f = box(-0.5, 0.5, -0.5, 0.5, 3, 4);
  f.mass_kg = 2.0;
  const std::vector<FragmentState> frags{f};
  const std::vector<int> candidates{0};
  // 40 N on 2 kg: 20 m/s^2, an arrow of 1 m to the right at the default 0.05 m per m/s^2.
  const std::vector<AppliedForce> forces{{0, {40.0, 0.0, 0.0}}};
  StepSnapshot snap = snapshot(square_camera(), frags);
  snap.candidates = candidates;
  snap.forces = forces;
  FrameStyle style = square_style();
  style.overlays.candidates = true;
  style.overlays.forces = true;
  style.overlays.central = true;
  FrameRenderer r(sky_scene(), style);
  const Image img = r.render(snap);
  // The near face's left edge at x / z = -0.5 / 3: column 83.3; the arrow from the centre (depth
  // 3.5) to x = 1: columns 100 .. 128.6 on row 100.
  EXPECT_TRUE(img.at(83, 110) == kCandidateColour || img.at(84, 110) == kCandidateColour);
  EXPECT_EQ(img.at(120, 100), kForceColour);
  EXPECT_FALSE(img.at(135, 100) == kForceColour);
  EXPECT_EQ(img.at(50, 120), kCentralColour);  // the central half: columns 50 .. 150
  EXPECT_EQ(img.at(10, 10), render({f}).at(10, 10));
}

TEST(FrameRenderer, SameSnapshotGivesTheSameBytes) {
  const Scene scene;  // with ground
  std::vector<FragmentState> frags;
  for (int i = 0; i < 50; ++i) {
    FragmentState f = box(-0.2, 0.2, -0.2, 0.2, 1.0, 1.4);
    f.position_m += Eigen::Vector3d(0.1 * (i % 7) - 0.3, 0.05 * (i % 5), -0.3 * i);
    f.rotation =
        Eigen::AngleAxisd(0.3 * i, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    frags.push_back(f);
  }
  CameraPose cam = square_camera();
  cam.eye_m = {0.0, 1.0, 0.0};
  for (FragmentState& f : frags) f.position_m.y() += 1.0;
  FrameStyle style = square_style();
  style.overlays.cuts = true;
  FrameRenderer r(scene, style);
  const Image a = r.render(snapshot(cam, frags));
  const Image b = r.render(snapshot(cam, frags));
  EXPECT_EQ(a.bytes(), b.bytes());
  EXPECT_EQ(encode_png(a), encode_png(b));
  EXPECT_EQ(a.bytes(), FrameRenderer(scene, style).render(snapshot(cam, frags)).bytes());
}

// --- Faded fragments (the fade strategy's opacities) --------------------------------------------

Image render_faded(const std::vector<FragmentState>& frags, const std::vector<float>& opacity) {
  FrameRenderer r(sky_scene(), square_style());
  StepSnapshot s = snapshot(square_camera(), frags);
  s.opacity = opacity;
  return r.render(s);
}

TEST(FrameRenderer, FadedFragmentIsDrawnDitheredByItsOpacity) {
  // A plate in front of a wall: where the dither skips the plate's pixel, the wall shows.
  const FragmentState plate = box(-0.5, 0.5, -0.5, 0.5, 2.0, 2.001);
  const FragmentState wall = box(-3, 3, -3, 3, 4.0, 4.1);
  const Rgb plate_colour = shaded_colour(fragment_colour(0), kTowardCamera);
  const Rgb wall_colour = shaded_colour(fragment_colour(1), kTowardCamera);
  const Image opaque = render({plate, wall});
  // Opacity 1 draws exactly what no opacity draws.
  const Image ones = render_faded({plate, wall}, {1.0f, 1.0f});
  EXPECT_EQ(ones.bytes(), opaque.bytes());
  // At 0.25, 4 of every 16 pixels inside the plate's square (columns and rows 75..124, whole
  // 4 x 4 blocks from 76 to 123) are the plate's; the rest show the wall behind it.
  const Image quarter = render_faded({plate, wall}, {0.25f, 1.0f});
  int plate_px = 0;
  int wall_px = 0;
  for (int y = 76; y < 124; ++y) {
    for (int x = 76; x < 124; ++x) {
      ASSERT_EQ(opaque.at(x, y), plate_colour) << x << "," << y;
      plate_px += quarter.at(x, y) == plate_colour;
      wall_px += quarter.at(x, y) == wall_colour;
    }
  }
  EXPECT_EQ(plate_px, 48 * 48 / 4);
  EXPECT_EQ(wall_px, 48 * 48 * 3 / 4);
  // Invisible: the plate is not drawn at all, not even its cut.
  const Image gone = render_faded({plate, wall}, {0.0f, 1.0f});
  const FragmentState behind_eye = box(-0.5, 0.5, -0.5, 0.5, -3.0, -2.999);  // never drawn
  EXPECT_EQ(gone.bytes(), render({behind_eye, wall}).bytes());
}

}  // namespace
}  // namespace fragsim
