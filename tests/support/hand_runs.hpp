#pragma once
// Runs made by hand, played to an observer without physics: metrics and records tested on states
// worked out by hand.

#include <vector>

#include "control/geometry/fragment_state.hpp"
#include "metrics/trajectory_record.hpp"
#include "sim/run_observer.hpp"

namespace fragsim::test {

inline constexpr double kDt_s = 1.0 / 60.0;

// One run: the fragments' states at step 0, 1, ..., steps.
using Trajectory = std::vector<std::vector<FragmentState>>;

// n fragments on a line, falling at different speeds, over `steps` steps.
inline Trajectory make_run(int n, int steps) {
  Trajectory run(static_cast<std::size_t>(steps + 1));
  for (int k = 0; k <= steps; ++k) {
    for (int i = 0; i < n; ++i) {
      FragmentState f;
      f.position_m = {0.3 * i, 1.6 - 0.1 * (i + 1) * k, -8.0 + 0.25 * k};
      f.half_extents_m = {0.05, 0.05, 0.05};
      run[static_cast<std::size_t>(k)].push_back(f);
    }
  }
  return run;
}

inline void play(const Trajectory& run, RunObserver& observer) {
  const RunInfo info{nullptr, "test", static_cast<int>(run.front().size()),
                     static_cast<int>(run.size()) - 1, kDt_s};
  StepSnapshot snap;
  snap.fragments = run.front();
  observer.begin(info, snap);
  for (std::size_t k = 1; k < run.size(); ++k) {
    snap.step = static_cast<int>(k);
    snap.t_s = static_cast<double>(k) * kDt_s;
    snap.fragments = run[k];
    observer.observe(snap);
  }
  observer.end();
}

inline TrajectoryRecord record(const Trajectory& run) {
  TrajectoryRecord ref;
  play(run, ref);
  return ref;
}

}  // namespace fragsim::test
