#pragma once
// The strategy of a run of the tool. The controller library's strategies (edge-min, edge,
// deflect-all; strategies/strategy.hpp) answer forces and their activity, all a game asks of them.
// The tool's baselines answer more (`wall` puts a box in the world, `near-plane` moves the camera's
// near plane, `fade` draws fragments translucent). Those effects, and the path a strategy predicts
// with (which the time-against-error bench measures), are the tool's concern and live here; a
// library strategy runs in the tool through LibraryStrategy.

#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "control/strategies/predictor.hpp"
#include "control/strategies/strategy.hpp"

namespace fragsim {

// A kinematic box the simulation must carry in front of the camera (the `wall` strategy).
struct CameraWallSpec {
  double distance_m = 0.0;  // centre of the box along the view direction
  double width_m = 0.0;
  double height_m = 0.0;
  double thickness_m = 0.0;
  double restitution = 0.0;
};

// What a strategy needs the world to contain besides fragments, ground and camera.
struct WorldNeeds {
  std::optional<CameraWallSpec> camera_wall;
};

// A strategy's answer in a run of the tool, the library's (forces, activity) and the effects on
// the camera and the drawing.
struct SceneStepOutput : StepOutput {
  std::optional<double> near_m;  // a camera near distance other than the scene's
  // Each fragment's opacity in the frame after this step, 0 (invisible) to 1. Empty means every
  // fragment is opaque, as for every strategy that draws fragments as they are.
  std::vector<float> opacity;

  void clear() {
    StepOutput::clear();
    near_m.reset();
    opacity.clear();
  }
};

class SceneStrategy {
 public:
  virtual ~SceneStrategy() = default;
  virtual std::string name() const = 0;
  virtual WorldNeeds needs() const { return {}; }
  // The path it predicts fragments with; the baselines, which do not predict, and edge-min are
  // measured against ODE's own discrete parabola.
  virtual Predictor path_predictor() const { return Predictor::kDiscrete; }
  // Called before the first step of every run.
  virtual void reset(int fragment_count) = 0;
  // Called once per step, before the physics step; `out` arrives cleared.
  virtual void step(const StepContext& ctx, SceneStepOutput& out) = 0;
};

// One of the library's strategies in a run of the tool, its forces and activity and nothing else.
class LibraryStrategy final : public SceneStrategy {
 public:
  explicit LibraryStrategy(std::unique_ptr<Strategy> inner,
                           Predictor predictor = Predictor::kDiscrete)
      : inner_(std::move(inner)), predictor_(predictor) {}
  std::string name() const override { return inner_->name(); }
  Predictor path_predictor() const override { return predictor_; }
  void reset(int fragment_count) override { inner_->reset(fragment_count); }
  void step(const StepContext& ctx, SceneStepOutput& out) override { inner_->step(ctx, out); }
  Strategy& inner() { return *inner_; }

 private:
  std::unique_ptr<Strategy> inner_;
  Predictor predictor_;
};

// A library strategy owned elsewhere, in a run of the tool (a benchmark that copies the strategy
// as it was at a step).
class LibraryStrategyRef final : public SceneStrategy {
 public:
  explicit LibraryStrategyRef(Strategy& inner) : inner_(inner) {}
  std::string name() const override { return inner_.name(); }
  void reset(int fragment_count) override { inner_.reset(fragment_count); }
  void step(const StepContext& ctx, SceneStepOutput& out) override { inner_.step(ctx, out); }

 private:
  Strategy& inner_;
};

// A strategy as the tool runs it, a SceneStrategy as it is or a library strategy wrapped.
template <class S>
std::unique_ptr<SceneStrategy> as_scene_strategy(std::unique_ptr<S> s) {
  if constexpr (std::is_base_of_v<SceneStrategy, S>) {
    return s;
  } else {
    return std::make_unique<LibraryStrategy>(std::move(s));
  }
}

}  // namespace fragsim
