// Keys a scene's own choices make moot, and keys that are not: each rule against the mode that
// makes the key count.

#include "sim/key_relevance.hpp"

#include <gtest/gtest.h>

namespace fragsim {
namespace {

TEST(KeyRelevance, TrackAndPlayerKeysCountInTheirModeOnly) {
  Scene s;
  EXPECT_EQ(why_no_effect(s, "camera.track_file"),
            "only camera.mode = track reads a track, and camera.mode = path");
  EXPECT_TRUE(why_no_effect(s, "camera.track_unit_m"));
  EXPECT_TRUE(why_no_effect(s, "camera.player_interval_s"));
  s.camera.mode = CameraMode::kTrack;
  EXPECT_FALSE(why_no_effect(s, "camera.track_file"));
  EXPECT_FALSE(why_no_effect(s, "camera.track_handedness"));
  EXPECT_EQ(why_no_effect(s, "camera.player_look_radius_m"),
            "only camera.mode = player draws the player's moves, and camera.mode = track");
  s.camera.mode = CameraMode::kPlayer;
  EXPECT_FALSE(why_no_effect(s, "camera.player_look_radius_m"));
  // The bounds play's live flight obeys in every mode are never moot.
  EXPECT_FALSE(why_no_effect(Scene{}, "camera.player_accel_mps2"));
  EXPECT_FALSE(why_no_effect(Scene{}, "camera.turn_rate_degps"));
}

TEST(KeyRelevance, TheObjectsSourceDecidesItsKeys) {
  Scene s;
  EXPECT_FALSE(why_no_effect(s, "object.splits"));
  EXPECT_FALSE(why_no_effect(s, "object.size_m"));
  EXPECT_TRUE(why_no_effect(s, "object.pieces"));
  EXPECT_TRUE(why_no_effect(s, "object.cluster"));
  s.object.pattern = DebrisPattern::kVoronoi;
  EXPECT_FALSE(why_no_effect(s, "object.pieces"));
  EXPECT_FALSE(why_no_effect(s, "object.gap"));
  EXPECT_TRUE(why_no_effect(s, "object.splits"));
  s.object.mesh_file = "/x/pieces.obj";
  for (const char* key : {"object.size_m", "object.splits", "object.pattern", "object.pieces",
                          "object.cluster", "object.gap"}) {
    EXPECT_EQ(why_no_effect(s, key),
              "the pieces come from object.mesh_file, as the file makes them")
        << key;
  }
  EXPECT_FALSE(why_no_effect(s, "object.density_kgpm3"));
  EXPECT_FALSE(why_no_effect(s, "object.centre_m"));
}

TEST(KeyRelevance, GroundRestAndAimFollowTheirSwitches) {
  Scene s;
  EXPECT_FALSE(why_no_effect(s, "ground.friction"));
  s.ground.enabled = false;
  EXPECT_TRUE(why_no_effect(s, "ground.height_m"));
  EXPECT_TRUE(why_no_effect(s, "simulation.rest_steps"));
  s.sim.cull_resting = true;
  EXPECT_FALSE(why_no_effect(s, "simulation.rest_steps"));
  EXPECT_TRUE(why_no_effect(s, "explosion.aim"));
  s.explosion.toward_camera_mps = 4.0;
  EXPECT_FALSE(why_no_effect(s, "explosion.aim"));
  // The strategies' keys: any command may run any strategy.
  EXPECT_FALSE(why_no_effect(Scene{}, "near-plane.margin_m"));
}

}  // namespace
}  // namespace fragsim
