#pragma once
// Strategies by name: the one place that knows every implementation.

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "sim/scene.hpp"
#include "strategies/strategy.hpp"

namespace fragsim {

// Every strategy name, in the order comparisons list them.
const std::vector<std::string>& strategy_names();

// A new strategy with its parameters taken from the scene's section of the same name. Throws
// std::invalid_argument naming the strategy (unknown name) or the parameter and its value.
std::unique_ptr<Strategy> make_strategy(std::string_view name, const Scene& scene);

}  // namespace fragsim
