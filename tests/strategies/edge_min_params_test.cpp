// edge-min's keys as a scene file writes them: the turn-rate bound may be inf (no bound).

#include "control/strategies/edge_min_params.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "sim/scene_file.hpp"

namespace fragsim {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The message a bad scene text raises (empty if it parses).
std::string error_of(const std::string& text) {
  try {
    parse_scene(text, "turn.ini");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(EdgeMinParams, TheTurnBoundIsNoneByDefault) {
  EXPECT_EQ(EdgeMinParams{}.camera_turn_degps, kInf);
  EXPECT_EQ(Scene{}.strategies.edge_min.camera_turn_degps, kInf);
}

TEST(EdgeMinParams, ASceneFileMaySayInfOrANumber) {
  EXPECT_EQ(parse_scene("[edge-min]\ncamera_turn_degps = inf\n", "turn.ini")
                .strategies.edge_min.camera_turn_degps,
            kInf);
  EXPECT_EQ(parse_scene("[edge-min]\ncamera_turn_degps = 90\n", "turn.ini")
                .strategies.edge_min.camera_turn_degps,
            90.0);
  // Written back as inf, read back the same.
  Scene s;
  s.strategies.edge_min.camera_turn_degps = kInf;
  const std::string ini = scene_to_ini(s);
  EXPECT_NE(ini.find("camera_turn_degps = inf\n"), std::string::npos);
  EXPECT_EQ(scene_to_ini(parse_scene(ini, "turn.ini")), ini);
}

TEST(EdgeMinParams, OtherNonNumbersAndNegativesAreRefused) {
  for (const char* bad : {"-1", "nan", "-inf", "1e7"}) {
    const std::string e = error_of(std::string("[edge-min]\ncamera_turn_degps = ") + bad + "\n");
    EXPECT_NE(e.find("camera_turn_degps"), std::string::npos) << bad << ": " << e;
  }
}

}  // namespace
}  // namespace fragsim
