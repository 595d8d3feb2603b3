#pragma once
// Numbers as text: the shortest form that reads back as the same double, identical on every
// platform (std::to_chars), so scene files round-trip and CSV files are byte-for-byte repeatable.

#include <charconv>
#include <string>

namespace fragsim {

inline void append_double(std::string& out, double v) {
  char buf[32];
  const auto res = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, res.ptr);
}

inline std::string format_double(double v) {
  std::string s;
  append_double(s, v);
  return s;
}

}  // namespace fragsim
