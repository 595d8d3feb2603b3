// `near-plane`'s keys (strategies/near_plane_params.cpp): each in its range, and a least near
// distance no farther than the camera's own near plane (the strategy only ever pulls it in);
// checked when the strategy is made, against the scene's camera (near_m 0.1 m by default).

#include "strategies/near_plane_params.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "sim/scene_strategies.hpp"

namespace fragsim {
namespace {

std::string error_of(const Scene& scene) {
  try {
    make_strategy("near-plane", scene);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(NearPlaneParams, LeastNearIsAtMostTheCamerasNearAndEachKeyInRange) {
  Scene scene;
  ASSERT_EQ(scene.camera.near_m, 0.1);
  EXPECT_EQ(error_of(scene), "");
  scene.strategies.near_plane.min_near_m = 0.1;  // equal: allowed
  EXPECT_EQ(error_of(scene), "");
  scene.strategies.near_plane.min_near_m = std::nextafter(0.1, 1.0);
  EXPECT_NE(error_of(scene).find("near-plane.min_near_m = 0.10000000000000002: must be <= "
                                 "camera.near_m = 0.1"),
            std::string::npos)
      << error_of(scene);
  scene.camera.near_m = 0.5;  // the rule follows the camera
  EXPECT_EQ(error_of(scene), "");
  scene = {};
  scene.strategies.near_plane.depth_bits = 33;  // [8, 32]
  EXPECT_NE(error_of(scene).find("near-plane.depth_bits"), std::string::npos) << error_of(scene);
  scene.strategies.near_plane.depth_bits = 32;
  EXPECT_EQ(error_of(scene), "");
  scene.strategies.near_plane.margin_m = -0.01;  // [0, 100]
  EXPECT_NE(error_of(scene).find("near-plane.margin_m"), std::string::npos) << error_of(scene);
}

}  // namespace
}  // namespace fragsim
