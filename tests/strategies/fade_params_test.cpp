// `fade`'s keys (strategies/fade_params.cpp): each in its range, and end_m nearer the eye than
// start_m, checked when the strategy is made.

#include "strategies/fade_params.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>
#include <string>

#include "sim/scene_strategies.hpp"

namespace fragsim {
namespace {

TEST(FadeParams, EndMustBeNearerThanStartAndEachKeyInRange) {
  Scene scene;
  const auto error = [&scene]() -> std::string {
    try {
      make_strategy("fade", scene);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_EQ(error(), "");
  scene.strategies.get<FadeParams>().end_m = 1.0;  // equal to start_m: no ramp
  EXPECT_NE(error().find("fade.end_m = 1: must be < fade.start_m = 1"), std::string::npos)
      << error();
  scene.strategies.get<FadeParams>().end_m = 2.0;
  EXPECT_NE(error().find("fade.end_m"), std::string::npos) << error();
  scene.strategies.get<FadeParams>().end_m = -0.1;
  EXPECT_NE(error().find("fade.end_m"), std::string::npos) << error();
  scene.strategies.get<FadeParams>().end_m = 0.0;  // invisible only at the eye: allowed
  EXPECT_EQ(error(), "");
  scene.strategies.get<FadeParams>().start_m = std::numeric_limits<double>::quiet_NaN();
  EXPECT_NE(error().find("fade.start_m"), std::string::npos) << error();
  scene.strategies.get<FadeParams>().start_m = 0.0;
  EXPECT_NE(error().find("fade.start_m"), std::string::npos) << error();
}

}  // namespace
}  // namespace fragsim
