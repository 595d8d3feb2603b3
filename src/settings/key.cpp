#include "settings/key.hpp"

namespace fragsim::settings {

std::string Range::text() const {
  if (std::isinf(hi))
    return std::string(lo_open ? "must be > " : "must be >= ") + format_double(lo);
  if (std::isinf(lo))
    return std::string(hi_open ? "must be < " : "must be <= ") + format_double(hi);
  return "must be in " + std::string(lo_open ? "(" : "[") + format_double(lo) + ", " +
         format_double(hi) + (hi_open ? ")" : "]");
}

std::string help_text(std::initializer_list<std::string_view> parts) {
  std::string out;
  for (std::string_view p : parts) {
    if (p.empty()) continue;
    if (!out.empty()) out += "; ";
    out += p;
  }
  return out;
}

std::optional<std::string> real_rule(double v, const Range& range) {
  if (!std::isfinite(v)) return "must be finite";
  if (!range.contains(v)) return range.text();
  return std::nullopt;
}

std::optional<std::string> real_or_inf_rule(double v, const Range& range) {
  if (v == std::numeric_limits<double>::infinity()) return std::nullopt;
  // -inf and nan break the rule as a number out of range does, so the message says the rule.
  if (!std::isfinite(v) || !range.contains(v)) return range.text() + ", or inf";
  return std::nullopt;
}

std::optional<std::string> integer_rule(long long v, long long lo, long long hi) {
  if (v < lo || v > hi) {
    return "must be a whole number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  }
  return std::nullopt;
}

std::optional<std::string> vec3_rule(const Eigen::Vector3d& v, const Range& each) {
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(v[i])) return "each component must be finite";
    if (!each.contains(v[i])) return "each component " + each.text();
  }
  return std::nullopt;
}

std::string bad_text_message(const std::string& where, const std::string& key,
                             const std::string& text, const std::string& rule) {
  return where + ": " + key + " = '" + text + "': " + rule;
}

std::string bad_value_message(const std::string& key, const std::string& value,
                              const std::string& rule) {
  return key + " = " + value + ": " + rule;
}

}  // namespace fragsim::settings
