#pragma once
// The report's 3D player (compare --report) shows the pieces and the camera of each strategy's run
// over time, drawn by three.js in the page (report_viewer.js). The recorder is an observer; it
// keeps each run's piece poses at sampled steps, the pieces the strategy pushed and those the near
// plane cut (its own NearPlaneMetric, so the flags are the metric's), and never changes the run.
//
// The page must stay small and the same bytes for the same scene and seed, so the poses are
// quantised, positions as 16-bit integers over the run's bounding box (error at most the box's
// extent / 131,068 per axis), quaternion components as 16-bit integers (error at most 1/65,534),
// and sampled every `every` steps (viewer_sample_every), the last step always kept. A sample's
// flags cover every step since the previous sample, so subsampling hides no push and no hit.

#include <cstdint>
#include <string>
#include <vector>

#include "metrics/near_plane_metric.hpp"
#include "report/bundled_three_js.hpp"
#include "report/gltf_bake.hpp"
#include "sim/run_observer.hpp"
#include "sim/scene.hpp"

namespace fragsim {

// The encoded viewer data the report allows for all strategies together. With three.js (about
// 0.9 MB encoded) and the rest of the page, front.ini with every strategy stays under 30 MB.
inline constexpr double kViewerBudget_bytes = 24e6;

// Bytes per piece per sample once encoded (3 + 4 int16, one flag byte, base64's 4/3).
inline constexpr double kViewerPieceSample_bytes = 15.0 * 4.0 / 3.0;

// The sampling stride in steps that keeps `strategy_count` runs of `piece_count` pieces over
// `step_count` steps within kViewerBudget_bytes (1 when everything fits).
int viewer_sample_every(int piece_count, int step_count, int strategy_count);

// Bit flags of a piece at a sample.
inline constexpr std::uint8_t kViewerPushed = 1;   // the strategy applied a force to it
inline constexpr std::uint8_t kViewerNearHit = 2;  // it met the near rectangle (near_plane_metric)

// One run as the viewer plays it.
struct ViewerRun {
  std::string strategy;
  std::vector<int> steps;  // the sampled steps, 0 first, the last step last
  Eigen::Vector3f lo_m = Eigen::Vector3f::Zero(), hi_m = Eigen::Vector3f::Zero();
  // Sample-major, per sample and piece x y z (positions), x y z w (rotations), flags.
  std::vector<std::int16_t> position_q;
  std::vector<std::int16_t> rotation_q;
  std::vector<std::uint8_t> flags;
  std::vector<CameraPose> cameras;  // per sample
};

class ViewerRecorder final : public RunObserver {
 public:
  explicit ViewerRecorder(int every);
  void begin(const RunInfo& info, const StepSnapshot& initial) override;
  void observe(const StepSnapshot& snap) override;
  void end() override;

  int every() const { return every_; }
  const std::vector<BakeMesh>& meshes() const { return meshes_; }
  const std::vector<int>& piece_mesh() const { return piece_mesh_; }
  const std::vector<ViewerRun>& runs() const { return runs_; }

 private:
  void sample(const StepSnapshot& snap);

  int every_;
  int step_count_ = 0;
  NearPlaneMetric near_;
  std::vector<std::uint8_t> pending_;  // flags since the last sample
  std::vector<float> positions_m_;     // this run's samples before quantising
  std::vector<float> rotations_;
  ViewerRun run_;
  std::vector<BakeMesh> meshes_;
  std::vector<int> piece_mesh_;
  std::vector<ViewerRun> runs_;
};

// The 3D view's section of the page, its controls, canvas, data and scripts (three.js as a `data:`
// URL module, then report_viewer.js). `left` and `right` are the strategies shown at first (right
// may be empty, for one view). Without three.js, one paragraph saying why and how to get it.
std::string viewer_section_html(const Scene& scene, const ViewerRecorder& recorder,
                                const std::string& left, const std::string& right,
                                const BundledThreeJs& three);

// The line the page and stderr show when three.js is missing.
std::string viewer_missing_text(const BundledThreeJs& three);

}  // namespace fragsim
