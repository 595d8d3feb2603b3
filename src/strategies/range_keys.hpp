#pragma once
// Scene keys whose rule is a range the library states (strategies/param_range.hpp). The keys of
// the library's strategies take each number's legal values from the library's own table, so a
// scene file and a game's def refuse the same values. Only the text (name, unit, help) is the
// tool's.

#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

#include "control/strategies/param_range.hpp"
#include "settings/key.hpp"

namespace fragsim {

// The range named `name`; throws std::logic_error when `ranges` has none (a key the library does
// not know of, a slip in the tool's table, which tests/strategies/range_keys_test.cpp finds).
const ParamRange& library_range(std::span<const ParamRange> ranges, std::string_view name);

// The interval of `range` as a key's rule (its +inf, if allowed, is the key's kind real_or_inf).
settings::Range key_range(const ParamRange& range);

// A number key named `name`, its rule the library's range of that name, real or real_or_inf
// when the range allows +inf.
template <class Owner>
settings::Key<Owner> ranged_real(std::span<const ParamRange> ranges, const char* name,
                                 std::string_view unit, std::string_view help, double Owner::*m) {
  const ParamRange& r = library_range(ranges, name);
  if (r.whole) throw std::logic_error(std::string(name) + ": a whole-number range");
  return r.inf_ok ? settings::real_or_inf(name, unit, help, m, key_range(r))
                  : settings::real(name, unit, help, m, key_range(r));
}

// A whole-number key named `name`, in the library's range of that name.
template <class Owner, class Int>
settings::Key<Owner> ranged_integer(std::span<const ParamRange> ranges, const char* name,
                                    std::string_view unit, std::string_view help, Int Owner::*m) {
  const ParamRange& r = library_range(ranges, name);
  if (!r.whole || r.lo_open || r.hi_open || r.inf_ok) {
    throw std::logic_error(std::string(name) + ": not a closed whole-number range");
  }
  return settings::integer(name, unit, help, m, static_cast<long long>(r.lo),
                           static_cast<long long>(r.hi));
}

}  // namespace fragsim
