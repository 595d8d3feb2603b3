#pragma once
// One fragment fired along a known line at a still camera (test::single_fragment), run through a
// strategy by name with every step recorded: the fixture of the per-strategy tests.

#include <string>

#include <Eigen/Core>

#include "support/test_scenes.hpp"

namespace fragsim::test {

inline RecordedRun run(const Scene& scene, const std::string& strategy) {
  return run_recorded(scene, strategy);
}

// 10 m ahead, 3 cm right of and 2 cm above the view axis, flying straight at the lens.
inline const Eigen::Vector3d kAtLens{0.03, 1.62, -10.0};
// The same line 2 m to the right.
inline const Eigen::Vector3d kBeside{2.03, 1.62, -10.0};

}  // namespace fragsim::test
