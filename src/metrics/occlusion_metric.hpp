#pragma once
// Screen occlusion (docs/method.md section 6). After every step each fragment's box (or, for a
// convex piece, its hull, i.e. the vertices and the points where its edges cross the plane) is
// clipped at the near plane in force then, projected, and its 2-D convex hull rasterised on a pixel
// grid; the covered share of the viewport and of a central region (where the action is) form
// per-step series, summarised as mean and max over the run, with the largest share one fragment
// covered.
//
// The raster has grid_width_px columns and max(1, round(width / aspect)) rows; pixel (col, row)
// spans [col, col + 1] x [row, row + 1] with x to the right and y DOWN (row 0 is the top of the
// screen), the viewport [-1, 1]^2 in NDC mapping onto [0, width] x [0, height]. A pixel is covered
// when its centre lies inside the hull or on its boundary (closed hull). Only the near plane and
// the side planes clip; the far plane does not (a fragment beyond it is a speck, not an occluder).
//
// A frame with opacities (StepSnapshot::opacity, the `fade` strategy) counts each fragment by
// its alpha. A pixel is covered by 1 - prod(1 - alpha) over the fragments whose hull holds its
// centre (what blending them in any order gives), and the largest share one fragment covered is
// its pixels times its alpha. An invisible fragment (alpha 0) covers nothing.

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "control/geometry/frustum.hpp"
#include "metrics/run_summary.hpp"
#include "sim/run_observer.hpp"
#include "sim/scene.hpp"

namespace fragsim {

class OcclusionMetric final : public RunObserver {
 public:
  explicit OcclusionMetric(const MetricsDef& def);

  void begin(const RunInfo& info, const StepSnapshot& initial) override;
  void observe(const StepSnapshot& snap) override;
  // Sets the occlusion_* fields to the mean and max over steps 1..N of the per-step shares, and the
  // largest share one fragment covered in any of those steps (0 for a run without steps).
  void fill(RunSummary& summary) const;

  // Covered share of the viewport and of the central region in each step (index = step - 1; the
  // initial snapshot given to begin() is not part of the series).
  const std::vector<double>& viewport_share_per_step() const { return viewport_share_; }
  const std::vector<double>& central_share_per_step() const { return central_share_; }
  // Largest share of the viewport covered by one fragment, over steps 1..N.
  double single_fragment_share_max() const { return single_max_; }

  // The raster, fixed by begin(); the central region is columns [x0, x1) and rows [y0, y1).
  int width_px() const { return width_px_; }
  int height_px() const { return height_px_; }
  int central_x0_px() const { return central_x0_; }
  int central_x1_px() const { return central_x1_; }
  int central_y0_px() const { return central_y0_; }
  int central_y1_px() const { return central_y1_; }
  // The last observed step's coverage, row-major from the top row; 1 = covered (by any fragment
  // drawn, whatever its alpha).
  const std::vector<std::uint8_t>& coverage() const { return coverage_; }

 private:
  int grid_width_px_;
  double central_fraction_;

  int width_px_ = 0;
  int height_px_ = 0;
  int central_x0_ = 0;
  int central_x1_ = 0;
  int central_y0_ = 0;
  int central_y1_ = 0;
  std::vector<std::uint8_t> coverage_;          // reused every step, so a step allocates nothing
  std::vector<double> transmittance_;           // prod(1 - alpha) per pixel, for translucent frames
  std::vector<Eigen::Vector3d> hull_vertices_;  // a convex piece's, in camera space (scratch)
  std::vector<ScreenPoint> hull_points_;        // its clipped, projected points and hull (scratch)
  std::vector<double> viewport_share_;
  std::vector<double> central_share_;
  double single_max_ = 0.0;
};

}  // namespace fragsim
