// Strategies see the camera's present only. With the blast aimed at where the camera is at t = 0,
// two cameras that agree up to the end of step k and part after must give every strategy the same
// inputs, hence bit-identical outputs, for steps 0..k. A strategy that read the camera's future
// would fail this.

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "experiments/evaluation.hpp"
#include "sim/player_camera.hpp"
#include "sim/scene_file.hpp"
#include "sim/scene_strategies.hpp"
#include "sim/simulation.hpp"
#include "support/test_scenes.hpp"

namespace fragsim {
namespace {

// front.ini, smaller, with a player's camera replayed as a track.
Scene aimed_scene() {
  Scene s = load_scene(std::string(FRAGSIM_DATA_DIR) + "/scenes/front.ini");
  s.object.splits = 6;
  s.sim.duration_s = 1.5;
  s.explosion.aim = ExplosionAim::kPresent;
  s.camera.mode = CameraMode::kPlayer;
  s.camera.max_speed_mps = 4.0;
  return s;
}

// The same samples up to and including index k + 1 (the end of step k); after it the eye
// reverses its last motion and the view drops by 20 degrees.
std::vector<CameraSample> parted_after(std::vector<CameraSample> s, std::size_t k) {
  for (std::size_t i = k + 2; i < s.size(); ++i) {
    const Eigen::Vector3d step = s[i - 1].eye_m - s[i - 2].eye_m;
    s[i].eye_m = s[i - 1].eye_m - step;
    const double a = 20.0 * kPi / 180.0;
    const Eigen::Vector3d f = s[i].forward;
    const Eigen::Vector3d right = f.cross(s[i].up);
    s[i].forward = std::cos(a) * f - std::sin(a) * s[i].up;
    s[i].up = right.cross(s[i].forward).normalized();
    s[i].forward.normalize();
  }
  return s;
}

std::vector<test::Recorder::Step> run(const Scene& scene, const std::string& strategy) {
  test::Recorder rec;
  RunObserver* observers[] = {&rec};
  auto s = make_strategy(strategy, scene);
  simulate(scene, *s, observers);
  return rec.steps;
}

TEST(CameraNoPeeking, EveryStrategyGivesTheSameOutputUntilTheCamerasPart) {
  Scene base = aimed_scene();
  const std::vector<CameraSample> player = player_track(base);
  const std::size_t k = 30;  // the cameras part after step 30 (t = 0.5 s)
  Scene a = base;
  a.camera.mode = CameraMode::kTrack;
  a.camera.track_samples = player;
  Scene b = a;
  b.camera.track_samples = parted_after(player, k);
  ASSERT_EQ(a.camera.track_samples[k + 1].eye_m, b.camera.track_samples[k + 1].eye_m);
  ASSERT_NE(a.camera.track_samples[k + 2].eye_m, b.camera.track_samples[k + 2].eye_m);

  int strategies_that_differ_later = 0;
  for (const char* name : {"none", "wall", "deflect-all", "near-plane", "edge", "edge-min"}) {
    const auto ra = run(a, name);
    const auto rb = run(b, name);
    ASSERT_EQ(ra.size(), rb.size());
    // Snapshot j + 1 holds what the strategy did in step j.
    for (std::size_t j = 0; j <= k; ++j) {
      const auto& x = ra[j + 1];
      const auto& y = rb[j + 1];
      ASSERT_EQ(x.forces.size(), y.forces.size()) << name << " step " << j;
      for (std::size_t i = 0; i < x.forces.size(); ++i) {
        EXPECT_EQ(x.forces[i].fragment, y.forces[i].fragment) << name << " step " << j;
        EXPECT_EQ(x.forces[i].force_N, y.forces[i].force_N) << name << " step " << j;
      }
      EXPECT_EQ(x.candidates, y.candidates) << name << " step " << j;
      EXPECT_EQ(x.near_m, y.near_m) << name << " step " << j;
      EXPECT_EQ(x.camera_hits, y.camera_hits) << name << " step " << j;
      for (std::size_t i = 0; i < x.fragments.size(); ++i) {
        ASSERT_EQ(x.fragments[i].position_m, y.fragments[i].position_m) << name << " step " << j;
      }
    }
    bool differ = false;
    for (std::size_t j = k + 1; j + 1 < ra.size() && !differ; ++j) {
      differ = ra[j + 1].candidates != rb[j + 1].candidates ||
               ra[j + 1].forces.size() != rb[j + 1].forces.size() ||
               ra[j + 1].near_m != rb[j + 1].near_m;
    }
    strategies_that_differ_later += differ ? 1 : 0;
  }
  // The test can fail: the controllers do react to the parted cameras after step k.
  EXPECT_GE(strategies_that_differ_later, 2);
}

// Aiming at the future peeks by design: the same parted cameras then give different blasts.
TEST(CameraNoPeeking, FutureAimPeeksByDesign) {
  Scene a = aimed_scene();
  a.explosion.aim = ExplosionAim::kFuture;
  const std::vector<CameraSample> player = player_track(a);
  a.camera.mode = CameraMode::kTrack;
  a.camera.track_samples = player;
  Scene b = a;
  b.camera.track_samples = parted_after(player, 30);
  const auto ra = run(a, "none");
  const auto rb = run(b, "none");
  EXPECT_NE(ra[0].fragments[0].velocity_mps, rb[0].fragments[0].velocity_mps);
}

}  // namespace
}  // namespace fragsim
