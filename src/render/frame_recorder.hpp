#pragma once
// Keeps copies of the snapshots of chosen steps, per strategy, so frames are drawn from the very
// run the metrics measured (no second simulation). Attach it to evaluate() or compare() as an
// extra observer; it never changes the run.

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "sim/run_observer.hpp"

namespace fragsim {

// An owned copy of a StepSnapshot's data. A fragment's shape is still a pointer; FrameRecorder
// points it at a copy it owns.
struct RecordedFrame {
  int step = 0;
  double t_s = 0.0;
  CameraPose camera;
  Eigen::Vector3d camera_velocity_mps = Eigen::Vector3d::Zero();
  Eigen::Vector3d camera_body_half_m = Eigen::Vector3d::Zero();
  std::vector<FragmentState> fragments;
  std::vector<AppliedForce> forces;
  std::vector<int> candidates;
  std::vector<int> capped;
  std::vector<int> camera_hits;
  std::vector<float> opacity;  // empty if all opaque

  explicit RecordedFrame(const StepSnapshot& snap);
  // A snapshot whose spans point into this frame (valid while it lives, unmoved).
  StepSnapshot view() const;
};

class FrameRecorder final : public RunObserver {
 public:
  // The steps to keep (0 = the explosion); order and repeats do not matter.
  explicit FrameRecorder(std::vector<int> steps);

  void begin(const RunInfo& info, const StepSnapshot& initial) override;
  void observe(const StepSnapshot& snap) override;

  // The strategies recorded, in the order they ran (a rerun of a name replaces its frames).
  std::vector<std::string> strategies() const;
  // The frames kept of `strategy`'s run in step order; null if it did not run.
  const std::vector<RecordedFrame>* frames(const std::string& strategy) const;
  // One frame of `strategy`'s run; null if it was not kept.
  const RecordedFrame* frame(const std::string& strategy, int step) const;

 private:
  struct Run {
    std::string strategy;
    std::vector<RecordedFrame> frames;
    // Copies of the convex shapes the frames show, by the run's own pointer, as the run's shapes
    // die with its simulation and frames are drawn later (a contact sheet of every strategy).
    // Per run, since a later run's shapes may reuse a freed one's address.
    std::map<const ConvexShape*, std::shared_ptr<const ConvexShape>> shapes;
  };
  void keep(const StepSnapshot& snap);

  std::vector<int> steps_;  // sorted, unique
  std::vector<Run> runs_;
  Run* current_ = nullptr;
};

}  // namespace fragsim
