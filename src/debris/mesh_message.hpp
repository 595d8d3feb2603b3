#pragma once
// Text from a mesh file or its reader quoted in a message, on one line and short.

#include <algorithm>
#include <cstddef>
#include <string>
#include <string_view>

namespace fragsim {

// The text on one line, as the readers' (tinyobjloader's, tinygltf's) messages may span several.
inline std::string one_line(std::string s) {
  std::replace(s.begin(), s.end(), '\n', ' ');
  while (!s.empty() && (s.back() == ' ' || s.back() == '\r')) s.pop_back();
  return s;
}

// A token or a uri as a message shows it, printable (a control character as '?') and cut after
// max_chars with "..." (a data: uri can be megabytes).
inline std::string shown(std::string_view text, std::size_t max_chars) {
  std::string out;
  for (char c : text.substr(0, max_chars)) {
    out += static_cast<unsigned char>(c) < 0x20 || c == 0x7f ? '?' : c;
  }
  return text.size() > max_chars ? out + "..." : out;
}

}  // namespace fragsim
