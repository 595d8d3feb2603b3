#pragma once
// A number with a fixed count of decimals, as the report shows it: std::to_chars (no locale, the
// same text on every platform) and never "-0.0" (a tiny negative rounds to zero without a sign).

#include <charconv>
#include <cmath>
#include <string>

namespace fragsim {

inline std::string fixed_text(double v, int decimals) {
  if (std::abs(v) < 0.5 * std::pow(10.0, -decimals)) v = 0.0;
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
  if (res.ec != std::errc()) return "?";  // only beyond 1e40 or so: no value the report shows
  return std::string(buf, res.ptr);
}

}  // namespace fragsim
