#pragma once
// What a strategy declares about its parameters, beside their struct: one key per parameter
// (settings/key.hpp, with name, unit, help, range or choices) and the rules that join several of
// them, or one of them and the camera's frustum (the wall is sized to it, the near plane pulled in
// from it). The registry puts this in the strategy's scene section.

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "control/geometry/frustum.hpp"
#include "settings/key.hpp"

namespace fragsim {

// One of a strategy's own accuracy settings for the time-against-error bench (fragsim bench) to
// try alone against the scene as given. The bench knows no strategy and runs what each declares.
struct TuningVariant {
  std::string group;                                      // "predictor"
  std::string label;                                      // "predictor thesis"
  std::vector<std::pair<std::string, std::string>> keys;  // {"edge.predictor", "thesis"}
};

template <class Params>
struct ParamSpec {
  settings::Keys<Params> keys;  // in the order --help and config.ini list them
  // Rules across keys or with the camera's frustum. Throws InputError naming the key. Empty for
  // none.
  std::function<void(const Params&, const FrustumDef&)> rules;
  std::vector<TuningVariant> tuning{};  // in the order the bench tries them
};

}  // namespace fragsim
