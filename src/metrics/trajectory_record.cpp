#include "metrics/trajectory_record.hpp"

namespace fragsim {

void TrajectoryRecord::begin(const RunInfo& info, const StepSnapshot& initial) {
  fragments_ = info.fragment_count;
  steps_ = 0;
  positions_m_.clear();
  positions_m_.reserve(static_cast<std::size_t>(info.step_count + 1) *
                       static_cast<std::size_t>(info.fragment_count));
  append(initial);
}

void TrajectoryRecord::observe(const StepSnapshot& snap) {
  append(snap);
}

void TrajectoryRecord::append(const StepSnapshot& snap) {
  // Positions are looked up by step number, so a skipped or repeated snapshot would shift them.
  assert(snap.step == steps_);
  assert(snap.fragments.size() == static_cast<std::size_t>(fragments_));
  for (const FragmentState& f : snap.fragments) positions_m_.push_back(f.position_m);
  ++steps_;
}

}  // namespace fragsim
