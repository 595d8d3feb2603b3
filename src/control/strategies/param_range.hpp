#pragma once
// The legal values of a strategy's numeric parameter, as numbers. Each parameters' struct
// (edge_min_params.hpp, edge_params.hpp, deflect_all_params.hpp) lists one per field. This is the
// only statement of each rule. The C API checks a def against it (api/input_checks.cpp) and the
// tool builds its scene keys' ranges from it, so a def and a scene file refuse the same values.
// Nothing here reads or writes text.

#include <limits>
#include <span>
#include <string_view>

namespace fragsim {

struct ParamRange {
  const char* name;   // the member of the parameters' struct and its scene key, e.g. "margin_m"
  const char* field;  // the C def's field it is set from ("edge_min.margin_m"), or nullptr
  double lo;
  double hi;
  bool lo_open = false;  // lo itself is refused
  bool hi_open = false;  // hi itself is refused
  bool inf_ok = false;   // +inf is legal besides [lo, hi] ("no bound")
  bool whole = false;    // a whole-number member, so lo and hi are whole numbers

  // Whether `v` is legal. NaN and -inf never are; +inf only with inf_ok.
  constexpr bool admits(double v) const {
    if (v == std::numeric_limits<double>::infinity()) return inf_ok;
    if (!(v == v) || v == -std::numeric_limits<double>::infinity()) return false;
    return (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
  }
};

// The range named `name` in `ranges`; nullptr when there is none.
constexpr const ParamRange* find_range(std::span<const ParamRange> ranges, std::string_view name) {
  for (const ParamRange& r : ranges) {
    if (name == r.name) return &r;
  }
  return nullptr;
}

}  // namespace fragsim
