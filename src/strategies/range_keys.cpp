#include "strategies/range_keys.hpp"

#include <stdexcept>
#include <string>

namespace fragsim {

const ParamRange& library_range(std::span<const ParamRange> ranges, std::string_view name) {
  if (const ParamRange* r = find_range(ranges, name)) return *r;
  throw std::logic_error("the library states no range for " + std::string(name));
}

settings::Range key_range(const ParamRange& range) {
  return {range.lo, range.hi, range.lo_open, range.hi_open};
}

}  // namespace fragsim
