#pragma once
// `fade` is what game engines ship (Unity's VFX Camera Fade block, the dithered distance fades of
// Unreal and Godot). It leaves the physics alone and applies no force. A fragment that comes
// closer to the eye than start_m is drawn transparent in proportion, and not at all from end_m
// in. It answers an opacity per fragment (SceneStepOutput::opacity), which the metrics and the
// renderer read.
//
// "Distance to the eye" is that of the nearest point of the fragment's box (for a convex piece,
// the box about its centre of mass that holds it, FragmentState::half_extents_m), 0 with the eye
// inside. A large piece whose corner reaches the lens fades by that corner, as a per-object
// fade must, since the whole piece shares one opacity. The box of a hull is never farther than
// the hull, so a hull fades at the latest where its box says.

#include <vector>

#include "strategies/fade_params.hpp"
#include "strategies/scene_strategy.hpp"

namespace fragsim {

// The distance from `eye_m` to the nearest point of the fragment's (oriented) box.
double box_distance_m(const Eigen::Vector3d& eye_m, const FragmentState& f);

// The opacity at distance `distance_m` is 1 at start_m and beyond, 0 at end_m and nearer, linear
// between.
float fade_opacity(const FadeParams& params, double distance_m);

class FadeStrategy final : public SceneStrategy {
 public:
  explicit FadeStrategy(const FadeParams& params) : params_(params) {}
  std::string name() const override { return "fade"; }
  void reset(int) override {}
  void step(const StepContext& ctx, SceneStepOutput& out) override;

 private:
  FadeParams params_;
};

}  // namespace fragsim
