#pragma once
// Values as scene-file text, read strictly (the whole text, finite numbers) and written so they
// read back as the same bits. A bad text throws ValueError with the rule it breaks; the caller
// adds where the text came from.

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "io/trim.hpp"

namespace fragsim::settings {

// A text that breaks a key's rule, with what was expected, without the place or the key.
struct ValueError {
  std::string rule;
};

double parse_double(const std::string& text);  // finite
// A number as parse_double reads it, or +infinity spelled as strtod accepts it ("inf" or "infinity"
// in any case, with or without a leading '+'). Other non-finite text (-inf, nan) is returned as it
// reads, for the key's rule to refuse with its range.
double parse_double_or_inf(const std::string& text);
long long parse_integer(const std::string& text);  // whole
Eigen::Vector3d parse_vec3(const std::string& text);
std::string format_vec3(const Eigen::Vector3d& v);

// Points 'x y z; x y z; ...', at least one and at most 1000, each component in [-1e6, 1e6].
std::vector<Eigen::Vector3d> parse_points(const std::string& text);
std::string format_points(const std::vector<Eigen::Vector3d>& points);
std::optional<std::string> points_rule(const std::vector<Eigen::Vector3d>& points);

// One line without commas or quotes, so it survives config.ini and CSV cells.
std::optional<std::string> text_rule(const std::string& text);

}  // namespace fragsim::settings
