#pragma once
// Every fragment's position at every snapshot of a run. The `none` run's record is the reference
// that deviation_metric.hpp measures the other strategies against.

#include <Eigen/Core>
#include <cassert>
#include <span>
#include <vector>

#include "sim/run_observer.hpp"

namespace fragsim {

class TrajectoryRecord final : public RunObserver {
 public:
  void begin(const RunInfo& info, const StepSnapshot& initial) override;
  void observe(const StepSnapshot& snap) override;

  // Snapshots recorded, step 0 and every observed step, so position() takes 0 <= step < steps().
  int steps() const { return steps_; }
  int fragments() const { return fragments_; }
  const Eigen::Vector3d& position(int step, int fragment) const {
    assert(step >= 0 && step < steps_ && fragment >= 0 && fragment < fragments_);
    return positions_m_[index(step, fragment)];
  }
  // All fragments' positions at one step, indexed by fragment.
  std::span<const Eigen::Vector3d> at_step(int step) const {
    assert(step >= 0 && step < steps_);
    return {positions_m_.data() + index(step, 0), static_cast<std::size_t>(fragments_)};
  }

 private:
  std::size_t index(int step, int fragment) const {
    return static_cast<std::size_t>(step) * static_cast<std::size_t>(fragments_) +
           static_cast<std::size_t>(fragment);
  }
  void append(const StepSnapshot& snap);

  int fragments_ = 0;
  int steps_ = 0;
  std::vector<Eigen::Vector3d> positions_m_;  // step-major, all fragments of step 0, then step 1
};

}  // namespace fragsim
