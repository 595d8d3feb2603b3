#include "control/geometry/frustum.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "control/geometry/camera_pose.hpp"

namespace fragsim {
namespace {

TEST(Frustum, TanOfHalfFovAndCrossSection) {
  EXPECT_NEAR(tan_half_fovy(60.0), 1.0 / std::sqrt(3.0), 1e-15);
  const Frustum f(90.0, 2.0, 0.1, 100.0);  // tan(45 deg) = 1 up to rounding
  EXPECT_NEAR(f.tan_y(), 1.0, 1e-15);
  EXPECT_NEAR(f.tan_x(), 2.0, 1e-15);
  EXPECT_NEAR(f.half_height_at(3.0), 3.0, 1e-14);
  EXPECT_NEAR(f.half_width_at(3.0), 6.0, 1e-14);
}

TEST(Frustum, AgreesBitForBitWithTheCameraPose) {
  CameraPose cam;
  cam.fovy_deg = 47.0;
  cam.aspect = 1.7;
  cam.near_m = 0.13;
  const Frustum f = cam.frustum();
  for (const double z : {0.13, 1.0, 7.3, 250.0}) {
    EXPECT_EQ(f.half_height_at(z), cam.half_height_at(z));
    EXPECT_EQ(f.half_width_at(z), cam.half_width_at(z));
  }
  EXPECT_EQ(f.half_width_at(cam.near_m), cam.near_half_width_m());
  EXPECT_EQ(f.tan_y(), std::tan(0.5 * cam.fovy_deg * kPi / 180.0));
}

// fovy 90 deg, aspect 1: the side planes are |x| = z and |y| = z, at distance (|x| - z) / sqrt(2).
TEST(Frustum, SphereJustInsideOrOutsideEachSidePlane) {
  const Frustum f(90.0, 1.0, 0.5, 50.0);
  const double z = 4.0;
  const double r = 0.5;
  const double edge = z + std::sqrt(2.0) * r;  // centre offset at which the sphere touches a plane
  for (const double s : {-1.0, 1.0}) {
    EXPECT_TRUE(f.sphere_may_show({s * (edge - 1e-6), 0.0, z}, r)) << s;
    EXPECT_FALSE(f.sphere_may_show({s * (edge + 1e-6), 0.0, z}, r)) << s;
    EXPECT_TRUE(f.sphere_may_show({0.0, s * (edge - 1e-6), z}, r)) << s;
    EXPECT_FALSE(f.sphere_may_show({0.0, s * (edge + 1e-6), z}, r)) << s;
  }
  // Depth: wholly in front of the near plane (0.5) or beyond the far one (50).
  EXPECT_TRUE(f.sphere_may_show({0.0, 0.0, 0.5 - r + 1e-9}, r));
  EXPECT_FALSE(f.sphere_may_show({0.0, 0.0, 0.5 - r - 1e-9}, r));
  EXPECT_TRUE(f.sphere_may_show({0.0, 0.0, 50.0 + r - 1e-9}, r));
  EXPECT_FALSE(f.sphere_may_show({0.0, 0.0, 50.0 + r + 1e-9}, r));
  // With the eye as the front bound the same sphere in front of the near plane still shows.
  EXPECT_TRUE(f.sphere_may_show({0.0, 0.0, 0.5 - r - 1e-9}, r, 0.0));
  EXPECT_FALSE(f.sphere_may_show({0.0, 0.0, -r - 1e-9}, r, 0.0));
}

TEST(Frustum, NormalizedCoordinatesOfTheImageCorner) {
  const Frustum f(60.0, 16.0 / 9.0, 0.1, 500.0);
  const double z = 8.0;
  const Eigen::Vector2d n = f.normalized({f.half_width_at(z), -f.half_height_at(z), z});
  EXPECT_EQ(n.x(), 1.0);
  EXPECT_EQ(n.y(), -1.0);
}

TEST(Frustum, ImageCornersAndCentre) {
  const Frustum f(60.0, 2.0, 0.1, 500.0);
  const PixelProjection p(f, 200, 100);
  const double z = 5.0;
  const double hw = z * f.tan_x();
  const double hh = z * f.tan_y();
  const ScreenPoint top_right = p.project({hw, hh, z});
  EXPECT_NEAR(top_right.x, 200.0, 1e-12);
  EXPECT_NEAR(top_right.y, 0.0, 1e-12);
  const ScreenPoint bottom_left = p.project({-hw, -hh, z});
  EXPECT_NEAR(bottom_left.x, 0.0, 1e-12);
  EXPECT_NEAR(bottom_left.y, 100.0, 1e-12);
  const ScreenPoint centre = p.project({0.0, 0.0, z});
  EXPECT_EQ(centre.x, 100.0);
  EXPECT_EQ(centre.y, 50.0);
  // The direction through a pixel's centre projects back onto that centre.
  const ScreenPoint back = p.project(3.0 * p.pixel_direction(17, 82));
  EXPECT_NEAR(back.x, 17.5, 1e-12);
  EXPECT_NEAR(back.y, 82.5, 1e-12);
  EXPECT_EQ(p.scale_y_px(), 0.5 * 100 / f.tan_y());
}

}  // namespace
}  // namespace fragsim
