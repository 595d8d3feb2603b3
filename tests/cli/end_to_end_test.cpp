// The default scene, all the way through: the thesis's problem appears without control and the
// thesis's method reduces it.

#include <gtest/gtest.h>

#include "experiments/evaluation.hpp"
#include "sim/scene_file.hpp"

namespace fragsim {
namespace {

Scene front() {
  return load_scene(std::string(FRAGSIM_DATA_DIR) + "/scenes/front.ini");
}

TEST(EndToEnd, FrontSceneHasIntersectionsWithoutControlAndFewerWithEdge) {
  const Scene scene = front();
  ASSERT_EQ(scene.fragment_count(), 1728);
  const RunSummary none = evaluate(scene, "none").summary;
  const RunSummary edge = evaluate(scene, "edge").summary;
  // The bar for the default scene: at least 20 fragments reach the near plane or camera.
  EXPECT_GE(std::max(none.intersections.near_fragments, none.intersections.camera_hit_fragments),
            20);
  EXPECT_LT(edge.intersections.near_fragments, none.intersections.near_fragments);
  EXPECT_LT(edge.intersections.camera_hit_fragments, none.intersections.camera_hit_fragments);
  EXPECT_GT(edge.activity.candidates_initial, 0);
  EXPECT_EQ(none.activity.candidates_initial, 0);
}

TEST(EndToEnd, SameSceneAndSeedGiveTheSameNumbers) {
  const Scene scene = front();
  const Evaluation a = evaluate(scene, "edge");
  const Evaluation b = evaluate(scene, "edge");
  EXPECT_EQ(a.near_per_step, b.near_per_step);
  EXPECT_EQ(a.candidates_per_step, b.candidates_per_step);
  EXPECT_EQ(a.summary.activity.impulse_Ns, b.summary.activity.impulse_Ns);
}

}  // namespace
}  // namespace fragsim
