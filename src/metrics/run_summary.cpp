#include "metrics/run_summary.hpp"

#include <stdexcept>

#include "io/number_format.hpp"

namespace fragsim {
namespace {

// A column whose value is a member of RunSummary, or a member of one of its parts.
template <class T>
SummaryField field(const char* name, T RunSummary::*member) {
  return {name, SummaryField::Get<T>([member](RunSummary& s) { return &(s.*member); })};
}
template <class Part, class T>
SummaryField field(const char* name, Part RunSummary::*part, T Part::*member) {
  return {name,
          SummaryField::Get<T>([part, member](RunSummary& s) { return &((s.*part).*member); })};
}

std::string cell(const RunSummary& s, const SummaryField& c) {
  return std::visit(
      [&s](const auto& get) -> std::string {
        // Only read here; the getter takes a RunSummary& so one table serves reading and writing.
        const auto& v = *get(const_cast<RunSummary&>(s));
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
      [&s, &text](const auto& get) {
        auto& v = *get(s);
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
      field("scene", &RunSummary::scene),
      field("strategy", &RunSummary::strategy),
      field("seed", &RunSummary::seed),
      field("dt_s", &RunSummary::dt_s),
      field("fragments", &RunSummary::fragments),
      field("steps", &RunSummary::steps),
      field("near_fragments", &RunSummary::intersections, &IntersectionCounts::near_fragments),
      field("near_fragment_steps", &RunSummary::intersections,
            &IntersectionCounts::near_fragment_steps),
      field("camera_hit_fragments", &RunSummary::intersections,
            &IntersectionCounts::camera_hit_fragments),
      field("deviation_mean_m", &RunSummary::deviation, &DeviationStats::mean_m),
      field("deviation_max_m", &RunSummary::deviation, &DeviationStats::max_m),
      field("deviated_share", &RunSummary::deviation, &DeviationStats::deviated_share),
      field("occlusion_mean", &RunSummary::occlusion, &OcclusionStats::mean),
      field("occlusion_max", &RunSummary::occlusion, &OcclusionStats::max),
      field("central_occlusion_mean", &RunSummary::occlusion, &OcclusionStats::central_mean),
      field("central_occlusion_max", &RunSummary::occlusion, &OcclusionStats::central_max),
      field("single_fragment_occlusion_max", &RunSummary::occlusion,
            &OcclusionStats::single_fragment_max),
      field("exits_top", &RunSummary::exits, &ExitCounts::top),
      field("exits_bottom", &RunSummary::exits, &ExitCounts::bottom),
      field("exits_left", &RunSummary::exits, &ExitCounts::left),
      field("exits_right", &RunSummary::exits, &ExitCounts::right),
      field("exits_near", &RunSummary::exits, &ExitCounts::near),
      field("exits_stayed", &RunSummary::exits, &ExitCounts::stayed),
      field("near_misses", &RunSummary::intersections, &IntersectionCounts::near_misses),
      field("candidates_initial", &RunSummary::activity, &ActivityTotals::candidates_initial),
      field("candidates_max", &RunSummary::activity, &ActivityTotals::candidates_max),
      field("candidate_steps", &RunSummary::activity, &ActivityTotals::candidate_steps),
      field("forced_fragments", &RunSummary::activity, &ActivityTotals::forced_fragments),
      field("impulse_Ns", &RunSummary::activity, &ActivityTotals::impulse_Ns),
      field("max_accel_mps2", &RunSummary::activity, &ActivityTotals::max_accel_mps2),
      field("capped_forces", &RunSummary::activity, &ActivityTotals::capped_forces),
      field("unsaved_by_cap", &RunSummary::activity, &ActivityTotals::unsaved_by_cap),
      field("guarded", &RunSummary::activity, &ActivityTotals::guarded),
      field("ode_messages", &RunSummary::health, &PhysicsHealth::ode_messages),
      field("nonfinite_fragments", &RunSummary::health, &PhysicsHealth::nonfinite_fragments),
      field("wall_contacts", &RunSummary::activity, &ActivityTotals::wall_contacts),
      field("min_near_m", &RunSummary::activity, &ActivityTotals::min_near_m),
      field("depth_step_m", &RunSummary::activity, &ActivityTotals::depth_step_m),
      // Last, so the columns before it keep their places.
      field("deferred", &RunSummary::activity, &ActivityTotals::deferred),
      field("pushed_exits_top", &RunSummary::pushed_exits, &ExitCounts::top),
      field("pushed_exits_bottom", &RunSummary::pushed_exits, &ExitCounts::bottom),
      field("pushed_exits_left", &RunSummary::pushed_exits, &ExitCounts::left),
      field("pushed_exits_right", &RunSummary::pushed_exits, &ExitCounts::right),
      field("pushed_exits_near", &RunSummary::pushed_exits, &ExitCounts::near),
      field("pushed_exits_stayed", &RunSummary::pushed_exits, &ExitCounts::stayed),
      field("vanished_fragments", &RunSummary::intersections,
            &IntersectionCounts::vanished_fragments),
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
