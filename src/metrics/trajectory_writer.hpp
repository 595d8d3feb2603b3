#pragma once
// trajectories.csv rows, streamed while the run goes, as the file is large (one row per fragment
// per step). Opt-in, so a run without it does no per-fragment output work.

#include <ostream>
#include <string>
#include <vector>

#include "sim/run_observer.hpp"

namespace fragsim {

class TrajectoryWriter final : public RunObserver {
 public:
  // Writes the header; rows for every run observed follow, tagged with the strategy's name.
  explicit TrajectoryWriter(std::ostream& out);
  void begin(const RunInfo& info, const StepSnapshot& initial) override;
  void observe(const StepSnapshot& snap) override;
  void end() override;

  static const char* header();

 private:
  void write(const StepSnapshot& snap);

  std::ostream& out_;
  std::string strategy_;
  std::string buffer_;
  std::vector<char> candidate_;
  std::vector<Eigen::Vector3d> force_N_;
};

}  // namespace fragsim
