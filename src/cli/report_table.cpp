#include "cli/report_table.hpp"

#include "report/results_table.hpp"

namespace fragsim::cli {

void print_report(const Scene& scene, const std::vector<Evaluation>& runs, std::ostream& out) {
  out << results_text(results_table(scene, runs));
}

}  // namespace fragsim::cli
