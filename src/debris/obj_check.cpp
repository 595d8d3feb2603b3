#include "debris/obj_check.hpp"

#include <charconv>
#include <cmath>
#include <string_view>
#include <system_error>
#include <vector>

#include "debris/mesh_message.hpp"
#include "io/input_error.hpp"

namespace fragsim {
namespace {

bool is_blank(char c) {
  return c == ' ' || c == '\t';
}

// The line's whitespace-separated tokens up to a '#' (a comment), as tinyobjloader splits them.
std::vector<std::string_view> tokens_of(std::string_view line) {
  const auto hash = line.find('#');
  if (hash != std::string_view::npos) line = line.substr(0, hash);
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_blank(line[i])) ++i;
    const std::size_t start = i;
    while (i < line.size() && !is_blank(line[i])) ++i;
    if (i > start) out.push_back(line.substr(start, i - start));
  }
  return out;
}

// The lines as tinyobjloader reads them, ended by "\n", "\r\n" or a lone "\r".
std::vector<std::string_view> lines_of(std::string_view text) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\n' || text[i] == '\r') {
      out.push_back(text.substr(start, i - start));
      if (text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;
      start = i + 1;
    }
  }
  if (start < text.size()) out.push_back(text.substr(start));
  return out;
}

std::string_view without_plus(std::string_view t) {
  return !t.empty() && t.front() == '+' ? t.substr(1) : t;
}

// Why `t` is not a coordinate, or empty. Out of a double's range is a number (see the header).
std::string coordinate_rule(std::string_view t) {
  const std::string_view s = without_plus(t);
  double v = 0.0;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || r.ptr != s.data() + s.size() ||
      (r.ec != std::errc() && r.ec != std::errc::result_out_of_range)) {
    return "is not a number";
  }
  if (r.ec == std::errc() && !std::isfinite(v)) return "is not a finite number";
  return "";
}

// A token as a message shows it.
std::string shown_token(std::string_view t) {
  return shown(t, 40);
}

}  // namespace

void check_obj_text(const std::string& text, const std::string& path) {
  const std::vector<std::string_view> lines = lines_of(text);
  const auto is_keyword = [](const std::vector<std::string_view>& t, std::string_view k) {
    return !t.empty() && t.front() == k;
  };
  long long total = 0;
  for (std::string_view line : lines) {
    if (is_keyword(tokens_of(line), "v")) ++total;
  }
  long long before = 0;  // vertices read before the current line
  for (std::size_t n = 0; n < lines.size(); ++n) {
    const std::vector<std::string_view> t = tokens_of(lines[n]);
    const std::string at = path + ":" + std::to_string(n + 1) + ": ";
    if (is_keyword(t, "v")) {
      if (t.size() < 4) {
        throw InputError(at + "a vertex needs x y z, got " + std::to_string(t.size() - 1) +
                         " number" + (t.size() == 2 ? "" : "s"));
      }
      for (std::size_t i = 1; i < t.size(); ++i) {
        const std::string rule = coordinate_rule(t[i]);
        if (!rule.empty()) {
          throw InputError(at + "vertex coordinate '" + shown_token(t[i]) + "' " + rule);
        }
      }
      ++before;
    } else if (is_keyword(t, "f")) {
      for (std::size_t i = 1; i < t.size(); ++i) {
        const std::string_view index = without_plus(t[i].substr(0, t[i].find('/')));
        long long v = 0;
        const auto r = std::from_chars(index.data(), index.data() + index.size(), v);
        if (index.empty() || r.ec != std::errc() || r.ptr != index.data() + index.size()) {
          throw InputError(at + "face index '" + shown_token(t[i]) + "' is not a whole number");
        }
        if (v == 0) throw InputError(at + "face index 0: OBJ counts vertices from 1");
        if (v < 0 && -v > before) {
          throw InputError(at + "face index " + std::to_string(v) +
                           " names no vertex: it counts back from the last vertex before this "
                           "line, and there are " +
                           std::to_string(before));
        }
        if (v > total) {
          throw InputError(at + "face index " + std::to_string(v) +
                           " names no vertex: the file has " + std::to_string(total));
        }
      }
    }
  }
}

}  // namespace fragsim
