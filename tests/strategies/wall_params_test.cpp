// `wall`'s keys (strategies/wall_params.cpp): each in its range, and a wall thinner than twice its
// distance, so that the box stays in front of the eye; checked when the strategy is made. At the
// default distance of 0.6 m the limit is 1.2 m, itself refused.

#include "strategies/wall_params.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "sim/scene_strategies.hpp"

namespace fragsim {
namespace {

std::string error_of(const Scene& scene) {
  try {
    make_strategy("wall", scene);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(WallParams, ThicknessUnderTwiceTheDistanceAndEachKeyInRange) {
  Scene scene;
  ASSERT_EQ(scene.strategies.wall.distance_m, 0.6);
  EXPECT_EQ(error_of(scene), "");
  scene.strategies.wall.thickness_m = 1.2;
  EXPECT_NE(error_of(scene).find("wall.thickness_m = 1.2: must be < 2 wall.distance_m"),
            std::string::npos)
      << error_of(scene);
  scene.strategies.wall.thickness_m = std::nextafter(1.2, 0.0);
  EXPECT_EQ(error_of(scene), "");
  scene.strategies.wall.distance_m = 2.0;  // the limit moves with the distance: 4 m
  scene.strategies.wall.thickness_m = 3.9;
  EXPECT_EQ(error_of(scene), "");
  scene = {};
  scene.strategies.wall.margin = 0.99;  // [1, 100]
  EXPECT_NE(error_of(scene).find("wall.margin"), std::string::npos) << error_of(scene);
  scene.strategies.wall.margin = 1.0;
  EXPECT_EQ(error_of(scene), "");
  scene.strategies.wall.restitution = 1.01;  // [0, 1]
  EXPECT_NE(error_of(scene).find("wall.restitution"), std::string::npos) << error_of(scene);
  scene = {};
  scene.strategies.wall.distance_m = 0.0;  // (0, 1000]
  EXPECT_NE(error_of(scene).find("wall.distance_m"), std::string::npos) << error_of(scene);
}

}  // namespace
}  // namespace fragsim
