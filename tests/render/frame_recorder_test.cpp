// The frame recorder: the chosen steps of each run kept as they were, with their own copies of
// convex shapes and the fade strategy's opacities.

#include "render/frame_recorder.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "experiments/evaluation.hpp"
#include "render/frame_renderer.hpp"
#include "render/image.hpp"
#include "render/render_fixtures.hpp"
#include "support/convex_shapes.hpp"
#include "support/test_scenes.hpp"

namespace fragsim {
namespace {

using test::render;
using test::sky_scene;
using test::snapshot;
using test::square_camera;
using test::square_style;

TEST(FrameRecorder, KeepsTheChosenStepsOfEachRunAsTheyWere) {
  const Scene scene = test::single_fragment({0.0, 1.6, -10.0});
  FrameRecorder frames({10, 0, 3, 10, 1000});
  test::Recorder all;
  EvaluationOptions opts;
  opts.occlusion = false;
  opts.extra = {&frames, &all};
  evaluate(scene, "none", opts);
  const std::vector<RecordedFrame>* kept = frames.frames("none");
  ASSERT_NE(kept, nullptr);
  ASSERT_EQ(kept->size(), 3u);  // 0, 3, 10 (1000 is past the run's end)
  for (const RecordedFrame& f : *kept) {
    EXPECT_NEAR(f.t_s, f.step * scene.sim.dt_s, 1e-12);
    ASSERT_EQ(f.fragments.size(), 1u);
    EXPECT_EQ(f.fragments[0].position_m, all.steps[f.step].fragments[0].position_m);
    EXPECT_EQ(f.view().fragments.data(), f.fragments.data());
  }
  EXPECT_EQ(frames.frame("none", 3)->step, 3);
  EXPECT_EQ(frames.frame("none", 4), nullptr);
  EXPECT_EQ(frames.frames("edge"), nullptr);
  evaluate(scene, "edge", opts);
  EXPECT_EQ(frames.strategies(), (std::vector<std::string>{"none", "edge"}));
}

TEST(FrameRecorder, KeepsItsOwnCopyOfAConvexPiecesShape) {
  // A run's shapes die with its simulation, before the frames are drawn: the recorder's frame
  // must not point at them. Two fragments share one shape; the frame shares one copy too.
  auto shape = std::make_unique<ConvexShape>(test::regular_tetrahedron(0.5));
  const ConvexShape* original = shape.get();
  std::vector<FragmentState> frags{test::shaped_fragment(*shape, {0.0, 0.0, -5.0}),
                                   test::shaped_fragment(*shape, {1.0, 0.0, -5.0})};
  FrameRecorder frames({0});
  RunInfo info;
  info.strategy = "none";
  info.fragment_count = 2;
  frames.begin(info, snapshot(square_camera(), frags));
  const Image before = render(frags);
  shape.reset();
  const RecordedFrame* kept = frames.frame("none", 0);
  ASSERT_NE(kept, nullptr);
  const ConvexShape* copy = kept->fragments[0].shape;
  ASSERT_NE(copy, nullptr);
  EXPECT_NE(copy, original);
  EXPECT_EQ(kept->fragments[1].shape, copy);
  EXPECT_EQ(copy->vertices_m, test::regular_tetrahedron(0.5).vertices_m);
  FrameRenderer r(sky_scene(), square_style());
  EXPECT_EQ(r.render(kept->view()).bytes(), before.bytes());
}

TEST(FrameRecorder, KeepsTheOpacities) {
  const Scene scene = test::single_fragment({0.0, 1.6, -5.0}, 10.0);
  FrameRecorder frames({0, 27, 30});
  EvaluationOptions opts;
  opts.occlusion = false;
  opts.extra = {&frames};
  evaluate(scene, "fade", opts);
  EXPECT_TRUE(frames.frame("fade", 0)->opacity.empty());  // step 0: before the strategy spoke
  ASSERT_EQ(frames.frame("fade", 27)->opacity.size(), 1u);
  EXPECT_NEAR(frames.frame("fade", 27)->opacity[0], 0.2 / 0.75, 1e-6);  // 0.45 m from the eye
  EXPECT_EQ(frames.frame("fade", 30)->view().opacity[0], 0.0f);
}

}  // namespace
}  // namespace fragsim
