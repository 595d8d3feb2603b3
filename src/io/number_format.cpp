#include "io/number_format.hpp"

#include <charconv>
#include <cmath>

namespace fragsim {

void append_double(std::string& out, double v) {
  char buf[32];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, res.ptr);
}

std::string format_double(double v) {
  std::string s;
  append_double(s, v);
  return s;
}

std::string fixed_text(double v, int decimals) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  // DBL_MAX has 309 digits before the point, so with room for the decimals no value fails.
  char buf[309 + 2 + 64];
  if (decimals < 0) decimals = 0;
  if (decimals > 64) decimals = 64;
  const auto res = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
  std::string text(buf, res.ptr);
  // Strip the sign from a rounded zero after rounding, not by a threshold before it, as only the
  // digits know whether the value rounded to zero.
  if (!text.empty() && text.front() == '-' &&
      text.find_first_not_of("0.", 1) == std::string::npos) {
    text.erase(0, 1);
  }
  return text;
}

std::string percent_text(double share, int decimals) {
  return fixed_text(100.0 * share, decimals);
}

}  // namespace fragsim
