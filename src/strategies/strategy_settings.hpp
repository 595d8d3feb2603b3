#pragma once
// Every strategy's parameters, as a scene holds them. The built-in strategies' have a member
// each, because the tool's code and tests set them by name (scene.strategies.edge.k); any other
// strategy's live in a store by type, so adding a strategy does not touch this file.

#include <any>
#include <map>
#include <typeindex>

#include "strategies/strategy_params.hpp"

namespace fragsim {

class StrategySettings {
 public:
  WallParams wall;
  DeflectAllParams deflect_all;
  NearPlaneParams near_plane;
  EdgeParams edge;
  EdgeMinParams edge_min;

  // The parameters of a strategy without a member above; defaults until set.
  template <class Params>
  Params& get() {
    std::any& slot = store_[std::type_index(typeid(Params))];
    if (!slot.has_value()) slot = Params{};
    return *std::any_cast<Params>(&slot);
  }
  template <class Params>
  const Params& get() const {
    static const Params defaults{};
    const auto it = store_.find(std::type_index(typeid(Params)));
    return it == store_.end() ? defaults : *std::any_cast<Params>(&it->second);
  }

 private:
  std::map<std::type_index, std::any> store_;
};

}  // namespace fragsim
