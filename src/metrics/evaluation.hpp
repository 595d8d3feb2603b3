#pragma once
// Runs one strategy on a scene with the metric observers attached and gathers its summary. The
// comparison is a list of these on the same scene and seed.

#include <string>
#include <vector>

#include "metrics/run_summary.hpp"
#include "sim/scene.hpp"

namespace fragsim {

struct Evaluation {
  RunSummary summary;
  std::vector<int> near_per_step;
  std::vector<int> candidates_per_step;
  std::vector<double> near_m_per_step;
};

Evaluation evaluate(const Scene& scene, const std::string& strategy);

}  // namespace fragsim
