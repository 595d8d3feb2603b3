#include "metrics/run_summary.hpp"

#include <stdexcept>

#include "io/number_format.hpp"

namespace fragsim {
namespace {

std::string cell(const RunSummary& s, const SummaryField& c) {
  return std::visit(
      [&s](auto member) -> std::string {
        const auto& v = s.*member;
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, std::string>) {
          return v;
        } else if constexpr (std::is_same_v<T, double>) {
          return format_double(v);
        } else {
          return std::to_string(v);
        }
      },
      c.field);
}

void set_cell(RunSummary& s, const SummaryField& c, const std::string& text) {
  std::visit(
      [&s, &text](auto member) {
        auto& v = s.*member;
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, std::string>) {
          v = text;
        } else if constexpr (std::is_same_v<T, double>) {
          v = std::stod(text);
        } else if constexpr (std::is_same_v<T, int>) {
          v = std::stoi(text);
        } else {
          v = std::stoull(text);
        }
      },
      c.field);
}

}  // namespace

const std::vector<SummaryField>& summary_field_table() {
  static const std::vector<SummaryField> cols{
      {"scene", &RunSummary::scene},
      {"strategy", &RunSummary::strategy},
      {"seed", &RunSummary::seed},
      {"dt_s", &RunSummary::dt_s},
      {"fragments", &RunSummary::fragments},
      {"steps", &RunSummary::steps},
      {"near_fragments", &RunSummary::near_fragments},
      {"near_fragment_steps", &RunSummary::near_fragment_steps},
      {"camera_hit_fragments", &RunSummary::camera_hit_fragments},
      {"deviation_mean_m", &RunSummary::deviation_mean_m},
      {"deviation_max_m", &RunSummary::deviation_max_m},
      {"deviated_share", &RunSummary::deviated_share},
      {"occlusion_mean", &RunSummary::occlusion_mean},
      {"occlusion_max", &RunSummary::occlusion_max},
      {"central_occlusion_mean", &RunSummary::central_occlusion_mean},
      {"central_occlusion_max", &RunSummary::central_occlusion_max},
      {"single_fragment_occlusion_max", &RunSummary::single_fragment_occlusion_max},
      {"exits_top", &RunSummary::exits_top},
      {"exits_bottom", &RunSummary::exits_bottom},
      {"exits_left", &RunSummary::exits_left},
      {"exits_right", &RunSummary::exits_right},
      {"exits_near", &RunSummary::exits_near},
      {"exits_stayed", &RunSummary::exits_stayed},
      {"near_misses", &RunSummary::near_misses},
      {"candidates_initial", &RunSummary::candidates_initial},
      {"candidates_max", &RunSummary::candidates_max},
      {"candidate_steps", &RunSummary::candidate_steps},
      {"forced_fragments", &RunSummary::forced_fragments},
      {"impulse_Ns", &RunSummary::impulse_Ns},
      {"max_accel_mps2", &RunSummary::max_accel_mps2},
      {"capped_forces", &RunSummary::capped_forces},
      {"unsaved_by_cap", &RunSummary::unsaved_by_cap},
      {"guarded", &RunSummary::guarded},
      {"ode_messages", &RunSummary::ode_messages},
      {"nonfinite_fragments", &RunSummary::nonfinite_fragments},
      {"wall_contacts", &RunSummary::wall_contacts},
      {"min_near_m", &RunSummary::min_near_m},
      {"depth_step_m", &RunSummary::depth_step_m},
      // Last, so the columns before it keep their places.
      {"deferred", &RunSummary::deferred},
      {"pushed_exits_top", &RunSummary::pushed_exits_top},
      {"pushed_exits_bottom", &RunSummary::pushed_exits_bottom},
      {"pushed_exits_left", &RunSummary::pushed_exits_left},
      {"pushed_exits_right", &RunSummary::pushed_exits_right},
      {"pushed_exits_near", &RunSummary::pushed_exits_near},
      {"pushed_exits_stayed", &RunSummary::pushed_exits_stayed},
      {"vanished_fragments", &RunSummary::vanished_fragments},
  };
  return cols;
}

std::vector<std::string> summary_fields(const RunSummary& summary) {
  std::vector<std::string> out;
  for (const SummaryField& c : summary_field_table()) out.push_back(cell(summary, c));
  return out;
}

void set_summary_fields(RunSummary& summary, const std::vector<std::string>& fields) {
  const auto& cols = summary_field_table();
  if (fields.size() != cols.size()) throw std::runtime_error("summary fields: wrong count");
  for (std::size_t i = 0; i < cols.size(); ++i) set_cell(summary, cols[i], fields[i]);
}

}  // namespace fragsim
