#include "settings/value_text.hpp"

#include <charconv>
#include <cmath>
#include <sstream>

#include "io/number_format.hpp"

namespace fragsim::settings {

double parse_double(const std::string& text) {
  const std::string s = trim(text);
  double v = 0.0;
  const auto res = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || res.ec != std::errc() || res.ptr != s.data() + s.size()) {
    throw ValueError{"not a number"};
  }
  if (!std::isfinite(v)) throw ValueError{"must be finite"};
  return v;
}

double parse_double_or_inf(const std::string& text) {
  std::string s = trim(text);
  // from_chars reads "inf" and "infinity" in any case, but not the '+' strtod also takes.
  if (s.size() > 1 && s[0] == '+' && (s[1] == 'i' || s[1] == 'I')) s.erase(0, 1);
  double v = 0.0;
  const auto res = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || res.ec != std::errc() || res.ptr != s.data() + s.size()) {
    throw ValueError{"not a number"};
  }
  return v;
}

long long parse_integer(const std::string& text) {
  const std::string s = trim(text);
  long long v = 0;
  const auto res = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || res.ec != std::errc() || res.ptr != s.data() + s.size()) {
    throw ValueError{"not a whole number"};
  }
  return v;
}

Eigen::Vector3d parse_vec3(const std::string& text) {
  std::string s = text;
  for (char& c : s) {
    if (c == ',') c = ' ';
  }
  std::istringstream in(s);
  Eigen::Vector3d v;
  std::string word;
  int n = 0;
  while (in >> word) {
    if (n == 3) throw ValueError{"expected three numbers x y z"};
    v[n++] = parse_double(word);
  }
  if (n != 3) throw ValueError{"expected three numbers x y z"};
  return v;
}

std::string format_vec3(const Eigen::Vector3d& v) {
  return format_double(v.x()) + " " + format_double(v.y()) + " " + format_double(v.z());
}

std::optional<std::string> points_rule(const std::vector<Eigen::Vector3d>& points) {
  if (points.empty()) return "expected at least one point 'x y z'";
  if (points.size() > 1000) return "at most 1000 points";
  for (const Eigen::Vector3d& p : points) {
    for (int i = 0; i < 3; ++i) {
      // Written as a negation so that NaN breaks the rule too.
      if (!(std::abs(p[i]) <= 1e6)) return "each component must be in [-1e6, 1e6]";
    }
  }
  return std::nullopt;
}

std::vector<Eigen::Vector3d> parse_points(const std::string& text) {
  std::vector<Eigen::Vector3d> pts;
  std::istringstream in(text);
  std::string item;
  while (std::getline(in, item, ';')) {
    if (trim(item).empty()) continue;
    if (pts.size() == 1000) throw ValueError{"at most 1000 points"};
    pts.push_back(parse_vec3(item));
    for (int i = 0; i < 3; ++i) {
      if (std::abs(pts.back()[i]) > 1e6) throw ValueError{"each component must be in [-1e6, 1e6]"};
    }
  }
  if (pts.empty()) throw ValueError{"expected at least one point 'x y z'"};
  return pts;
}

std::string format_points(const std::vector<Eigen::Vector3d>& points) {
  std::string out;
  for (const Eigen::Vector3d& p : points) out += (out.empty() ? "" : "; ") + format_vec3(p);
  return out;
}

std::optional<std::string> text_rule(const std::string& text) {
  if (text.find_first_of(",\"\n") != std::string::npos) {
    return "must be one line without commas or quotes";
  }
  return std::nullopt;
}

}  // namespace fragsim::settings
