#pragma once
// Strategies by name, in one table, an entry per strategy with its name, what it does, its
// parameters' keys and how to make it. The scene parser, --help, config.ini, the --strategy lists
// and the parameters' validation all read the table, so adding a strategy is its own files and
// one entry. The registry knows nothing of the scene or the simulation (the strategies are the
// bottom layer), so the simulation hands it the settings (sim/scene_strategies.hpp makes them).

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "strategies/param_spec.hpp"
#include "strategies/scene_strategy.hpp"
#include "strategies/strategy_settings.hpp"

namespace fragsim {

struct StrategyEntry {
  std::string name;                       // also its scene section, [edge-min], --edge-min.margin_m
  std::string description;                // one line for --help
  settings::Keys<StrategySettings> keys;  // named "section.key"
  // The keys' rules on the values held (set in code or parsed), then the rules across keys.
  std::function<void(const StrategySettings&, const FrustumDef&)> check;
  // Only the rules across keys, as the parser has already checked each value against its key.
  std::function<void(const StrategySettings&, const FrustumDef&)> check_across;
  std::function<std::unique_ptr<SceneStrategy>(const StrategySettings&, const FrustumDef&)> make;
  std::vector<TuningVariant> tuning;  // what the time-against-error bench tries (ParamSpec)
};

using StrategyTable = std::vector<StrategyEntry>;

// A table entry for a strategy whose parameters `Params` are declared by `spec` and kept in
// `slot` (a member of StrategySettings) or, with no slot, in its store. `make` is called with
// the parameters, checked, and the camera.
template <class Params, class Make>
StrategyEntry strategy_entry(std::string name, std::string description,
                             const ParamSpec<Params>& spec, Make make,
                             Params StrategySettings::*slot = nullptr) {
  auto get = [slot](const StrategySettings& s) -> const Params& {
    return slot ? s.*slot : s.template get<Params>();
  };
  auto get_mut = [slot](StrategySettings& s) -> Params& {
    return slot ? s.*slot : s.template get<Params>();
  };
  StrategyEntry e;
  e.keys = settings::in_section<StrategySettings>(
      name, spec.keys, [ get, get_mut ](auto& s) -> auto& {
        if constexpr (std::is_const_v<std::remove_reference_t<decltype(s)>>) {
          return get(s);
        } else {
          return get_mut(s);
        }
      });
  e.check_across = [get, rules = spec.rules](const StrategySettings& s, const FrustumDef& c) {
    if (rules) rules(get(s), c);
  };
  e.check = [keys = e.keys, across = e.check_across](const StrategySettings& s,
                                                     const FrustumDef& c) {
    settings::check(keys, s);
    across(s, c);
  };
  e.make = [get, make](const StrategySettings& s, const FrustumDef& c) {
    return as_scene_strategy(make(get(s), c));
  };
  e.tuning = spec.tuning;
  e.name = std::move(name);
  e.description = std::move(description);
  return e;
}

// The tool's strategies, in the order comparisons list them.
const StrategyTable& strategy_table();

// Every strategy name, in the table's order.
const std::vector<std::string>& strategy_names();

// The names joined by `separator` ("none | wall | ...", "none,wall,...").
std::string join_strategy_names(const StrategyTable& table, std::string_view separator);

// For --help, one line per strategy with its name and what it does.
std::string describe_strategies(const StrategyTable& table);

// The entry named `name`; nullptr when there is none.
const StrategyEntry* find_strategy(std::string_view name,
                                   const StrategyTable& table = strategy_table());

// Whether the named strategy can be made with these parameters, without making it (its keys' rules
// on the values held, then its rules across keys and with the frustum). Throws InputError naming
// the strategy (unknown name) or the parameter and its value, one line.
void validate_strategy_settings(std::string_view name, const StrategySettings& settings,
                                const FrustumDef& camera,
                                const StrategyTable& table = strategy_table());

// The named strategy, validated first (validate_strategy_settings, the same errors).
std::unique_ptr<SceneStrategy> make_strategy(std::string_view name,
                                             const StrategySettings& settings,
                                             const FrustumDef& camera,
                                             const StrategyTable& table = strategy_table());

}  // namespace fragsim
