#pragma once
// The comparison as the terminal shows it, with a header line, one aligned table (a row per
// strategy, units in the headers), a legend and the verdict on the thesis's goals.

#include <ostream>
#include <vector>

#include "experiments/evaluation.hpp"
#include "sim/scene.hpp"

namespace fragsim::cli {

void print_report(const Scene& scene, const std::vector<Evaluation>& runs, std::ostream& out);

}  // namespace fragsim::cli
