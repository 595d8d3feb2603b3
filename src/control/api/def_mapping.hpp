#pragma once
// The C API's def (fragsim_controller_def) and the strategies' parameter structs, both ways, and
// the one place where a C field meets the parameter it sets. The controller reads a def through it;
// fragsim_default_controller_def and fragsim's control dump (src/experiments/control_dump.cpp)
// write one through it, so the replay test passes the library the very def the tool stands for.
//
// The C names differ from the scene keys (edge.k_Nms2 is [edge] k; one horizon_cap_s serves
// edge-min and edge), and edge-min's cover_horizon_s, cover_samples, cover_cells and cover_margin
// have no C field, so the library keeps their defaults.

#include <cstdint>
#include <cstring>
#include <optional>
#include <string_view>

#include "control/strategies/deflect_all_params.hpp"
#include "control/strategies/edge_min_params.hpp"
#include "control/strategies/edge_params.hpp"
#include "fragsim/control.h"

namespace fragsim::control {

// The value fragsim_default_controller_def puts in internal_value. A def with anything else skipped
// the defaults function, and its other fields may be garbage.
inline constexpr std::int32_t kDefCookie = 0x46534331;  // "FSC1"

// An enum field as the int the caller stored. A C caller may store any int in it, and loading an
// out-of-range value as the enum type is undefined in C++, so the bytes are read as an int.
template <class E>
int raw(const E& e) {
  static_assert(sizeof(E) == sizeof(int));
  int v;
  std::memcpy(&v, &e, sizeof v);
  return v;
}

// The def's parameters of each strategy. The enums are converted as they are, so a def whose enums
// are out of range must be refused before these read it.
EdgeMinParams edge_min_params(const fragsim_controller_def& def);
EdgeParams edge_params(const fragsim_controller_def& def);
DeflectAllParams deflect_all_params(const fragsim_controller_def& def);

// The def, cookie set, that runs `strategy` with these parameters; horizon_cap_s is the chosen
// strategy's (edge-min's for deflect-all, which has none). With the default parameters and
// edge-min, it is fragsim_default_controller_def().
fragsim_controller_def controller_def(fragsim_strategy strategy, const EdgeMinParams& edge_min,
                                      const EdgeParams& edge, const DeflectAllParams& deflect_all);

// The strategy of one of the names the strategies give themselves ("edge-min", "edge",
// "deflect-all"); nullopt for a strategy the library does not hold.
std::optional<fragsim_strategy> strategy_named(std::string_view name);

}  // namespace fragsim::control
