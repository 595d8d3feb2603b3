#include "strategies/registry.hpp"

#include <algorithm>
#include <sstream>

#include "control/strategies/deflect_all_strategy.hpp"
#include "control/strategies/edge_min_strategy.hpp"
#include "control/strategies/edge_strategy.hpp"
#include "strategies/fade_strategy.hpp"
#include "strategies/near_plane_strategy.hpp"
#include "strategies/none_strategy.hpp"
#include "strategies/wall_strategy.hpp"

namespace fragsim {
namespace {

struct NoParams {};

const ParamSpec<NoParams>& no_params() {
  static const ParamSpec<NoParams> spec;
  return spec;
}

}  // namespace

const StrategyTable& strategy_table() {
  using S = StrategySettings;
  using C = FrustumDef;
  static const StrategyTable table{
      strategy_entry("none", "no control; the reference run for deviation", no_params(),
                     [](const NoParams&, const C&) { return std::make_unique<NoneStrategy>(); }),
      strategy_entry(
          "wall",
          "a transparent kinematic box in front of the camera, moving with it, that fragments "
          "bounce off (thesis fig. 2.1)",
          wall_param_spec(),
          [](const WallParams& p, const C& c) {
            return std::make_unique<WallStrategy>(p, c.fovy_deg, c.aspect);
          },
          &S::wall),
      strategy_entry(
          "deflect-all",
          "every fragment approaching within range_m is pushed away from the view axis, with no "
          "prediction (fig. 2.2)",
          deflect_all_param_spec(),
          [](const DeflectAllParams& p, const C&) {
            return std::make_unique<DeflectAllStrategy>(p);
          },
          &S::deflect_all),
      strategy_entry(
          "near-plane",
          "physics untouched; the near plane is pulled toward the eye whenever a fragment would "
          "reach it (fig. 2.6)",
          near_plane_param_spec(),
          [](const NearPlaneParams& p, const C&) { return std::make_unique<NearPlaneStrategy>(p); },
          &S::near_plane),
      strategy_entry(
          "edge",
          "the thesis: ballistic prediction against the camera's reachable ball and the force "
          "(3.4) toward the near rectangle's nearest edge (docs/method.md section 3)",
          edge_param_spec(),
          [](const EdgeParams& p, const C&) {
            return std::make_unique<LibraryStrategy>(std::make_unique<EdgeStrategy>(p),
                                                     p.predictor);
          },
          &S::edge),
      strategy_entry(
          "edge-min",
          "the least constant push toward a screen edge that makes a threatening fragment miss "
          "the camera body and near rectangle, re-solved every step (docs/method.md section 4)",
          edge_min_param_spec(),
          [](const EdgeMinParams& p, const C&) { return std::make_unique<EdgeMinStrategy>(p); },
          &S::edge_min),
      strategy_entry(
          "fade",
          "physics untouched; a fragment nearer the eye than start_m is drawn transparent in "
          "proportion, invisible from end_m in (the engines' camera fade)",
          fade_param_spec(),
          [](const FadeParams& p, const C&) { return std::make_unique<FadeStrategy>(p); }),
  };
  return table;
}

const std::vector<std::string>& strategy_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> n;
    for (const StrategyEntry& e : strategy_table()) n.push_back(e.name);
    return n;
  }();
  return names;
}

std::string join_strategy_names(const StrategyTable& table, std::string_view separator) {
  std::string out;
  for (const StrategyEntry& e : table) {
    if (!out.empty()) out += separator;
    out += e.name;
  }
  return out;
}

std::string describe_strategies(const StrategyTable& table) {
  std::size_t width = 0;
  for (const StrategyEntry& e : table) width = std::max(width, e.name.size());
  std::string out = "Strategies (their parameters: the scene section of the same name):\n";
  // Wrapped to 80 columns as Boost wraps the options above it.
  const std::size_t indent = width + 4;
  for (const StrategyEntry& e : table) {
    std::string line = "  " + e.name + std::string(width - e.name.size() + 2, ' ');
    std::istringstream words(e.description);
    std::string word;
    bool first = true;
    while (words >> word) {
      if (!first && line.size() + 1 + word.size() > 80) {
        out += line + "\n";
        line = std::string(indent, ' ') + word;
      } else {
        line += (first ? "" : " ") + word;
      }
      first = false;
    }
    out += line + "\n";
  }
  return out;
}

const StrategyEntry* find_strategy(std::string_view name, const StrategyTable& table) {
  for (const StrategyEntry& e : table) {
    if (e.name == name) return &e;
  }
  return nullptr;
}

namespace {

// The named entry, its parameters checked; throws InputError.
const StrategyEntry& checked_entry(std::string_view name, const StrategySettings& settings,
                                   const FrustumDef& camera, const StrategyTable& table) {
  if (const StrategyEntry* e = find_strategy(name, table)) {
    e->check(settings, camera);
    return *e;
  }
  throw InputError("unknown strategy '" + std::string(name) +
                   "' (known: " + join_strategy_names(table, ", ") + ")");
}

}  // namespace

void validate_strategy_settings(std::string_view name, const StrategySettings& settings,
                                const FrustumDef& camera, const StrategyTable& table) {
  checked_entry(name, settings, camera, table);
}

std::unique_ptr<SceneStrategy> make_strategy(std::string_view name,
                                             const StrategySettings& settings,
                                             const FrustumDef& camera, const StrategyTable& table) {
  return checked_entry(name, settings, camera, table).make(settings, camera);
}

}  // namespace fragsim
