#pragma once
// edge-min's occlusion bound (EdgeMinParams::cover_max; docs/visibility.md, section 1). The
// `central_occlusion` metric rasterises every fragment's projected box over the middle of the
// screen after each step; this is the same quantity as a strategy can know it, ahead of time.
// - The paths are each fragment's ballistic path under gravity and the push already given this
//   step, as ODE's semi-implicit Euler steps it, seen from a camera that keeps its present velocity
//   and orientation (a strategy knows the camera's present, never its future).
// - Each fragment's shape is a disc of its box's mean projected area, so no orientation has to be
//   predicted (by Cauchy, a convex body's shadow averaged over orientations is a quarter of its
//   surface area). It is clipped at the near plane as a disc at the near distance, dropped when
//   wholly behind it.
// - The screen is a coarse grid of cover_cells columns over the central region, each cell covered
//   when its centre is inside a disc, at the steps ahead up to cover_horizon_s that the dyadic
//   schedule of cover_samples picks (every step near the present, sparser farther off, each on a
//   run step that stays sampled as it comes nearer, so a push planned for it is re-checked).
// Where the predicted share exceeds cover_max at some sample time, the fragments covering the most
// cells there (the nearest and largest on screen) are taken in turn, and each is given the least
// constant push, toward the screen edge of least push over weight, that takes its disc out of the
// region at every over-bound time it covers, within a_max; the grid is then redrawn with its pushed
// path. It stops once no sample is over the bound (aimed cover_margin under cover_max, for the
// prediction's own error), or no fragment is left that can still help. Re-solved every step from
// the new state, like the push against the camera, so a push fades once it is not needed, and the
// fragments pushed last step are taken first, so a plan stays with the fragments it started with.
// What a push added is taken back once the fragment is behind the camera and receding, where it
// cannot be seen again. The order is by cells covered at an over-bound sample per unit of push (the
// cheapest coverage to remove first, which clears the cloud from the region's borders inward), not
// of disc size. On front.ini at cover_max = 0.5 the largest-first order costs 1.27 m of mean
// deviation and 1181 N s, this one 1.23 m and 969 N s, both without cover_margin
// (docs/visibility.md).
//
// A step costs one pass over the fragments for each sample time (a position and a disc), cells
// filled only inside each disc's bounding rows and columns, and per pushed fragment one more pass
// over the samples. Fragments behind the near plane at every sample cost one test.

#include <array>
#include <cstddef>
#include <cstdint>
#include <tuple>
#include <utility>
#include <vector>

#include "control/memory/memory_resource.hpp"
#include "control/strategies/edge_min_params.hpp"
#include "control/strategies/strategy.hpp"

namespace fragsim {

class OcclusionBound {
 public:
  // Its state, its work space and its step's temporaries are allocated from `mem`.
  explicit OcclusionBound(MemoryResource* mem = default_memory_resource()) : mem_(mem) {}
  // Called before the first step of every run.
  void reset(int fragment_count);
  // Ways out, in edge-min's order: +up (top), -up (bottom), +right (right), -right (left).
  // `weights` in that order; 0 forbids a way.
  void step(const StepContext& ctx, const EdgeMinParams& params,
            const std::array<double, 4>& weights, StepOutput& out);

  // The last step's prediction, the sample times (from the start of the step) and the covered share
  // of the region at each, before and after the pushes it added. Empty when cover_max is off.
  const ResourceVector<double>& sample_times_s() const { return times_s_; }
  const ResourceVector<double>& predicted_before() const { return before_; }
  const ResourceVector<double>& predicted_after() const { return after_; }
  int pushed() const { return pushed_; }

 private:
  // One fragment's disc at one sample, as NDC centre and radii, or absent.
  struct Disc {
    double x = 0.0;
    double y = 0.0;
    double rx = 0.0;
    double ry = 0.0;
    bool present = false;
  };
  MemoryResource* mem_;
  int rows_ = 0;
  int cols_ = 0;
  ResourceVector<double> times_s_{mem_};
  ResourceVector<double> before_{mem_};
  ResourceVector<double> after_{mem_};
  int pushed_ = 0;
  // How many discs cover each cell at each sample, so a disc can be taken away again.
  ResourceVector<std::uint16_t> count_{mem_};
  ResourceVector<int> covered_{mem_};  // cells with count > 0, per sample
  // Each fragment's disc at each sample (fragment-major), and how many cells it covers.
  ResourceVector<Disc> disc_{mem_};
  ResourceVector<int> own_{mem_};
  // Per fragment, whether pushed in the last step and the velocity its pushes added (run state).
  ResourceVector<char> pushed_last_{mem_};
  ResourceVector<Eigen::Vector3d> added_mps_{mem_};

  int paint(int sample, const Disc& d, int delta);

  // The stages of step(), in order, and what they share (Path, Screen and Step, in the .cpp).
  struct Path;
  struct Screen;
  struct Step;
  // The sample times into times_s_; returns how many.
  int sample_times(const StepContext& ctx, const EdgeMinParams& params);
  // The grid cleared for k_samples samples of n fragments; returns its cells per sample.
  std::size_t make_grid(const CameraPose& cam, const EdgeMinParams& params, std::size_t n,
                        int k_samples);
  // What this bound's pushes added, taken back from fragments behind the camera.
  void brake_behind_camera(Step& s);
  void draw_paths(const Step& s, ResourceVector<Path>& paths);
  // Sample j's covered share, and whether it is over the bound.
  double share(const Step& s, int j) const;
  bool over(const Step& s, int j) const;
  bool any_over(const Step& s) const;
  // Fragment i's way out (4 for none) and least push.
  std::pair<std::size_t, double> plan(const Step& s, const Path& p, std::size_t i) const;
  void rank_fragments(const Step& s, const ResourceVector<Path>& paths,
                      ResourceVector<std::tuple<int, double, int>>& order);
  void push_in_order(Step& s, const ResourceVector<Path>& paths,
                     const ResourceVector<std::tuple<int, double, int>>& order);
  // A push on fragment i, added to its force in out (or a new one) and to added_mps_.
  void add_force(Step& s, std::size_t i, const Eigen::Vector3d& force_N);
};

}  // namespace fragsim
