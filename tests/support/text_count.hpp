#pragma once
// Counting a part's occurrences in generated text (SVG, HTML, CSV).

#include <cstddef>
#include <string>

namespace fragsim::test {

// How many times `part` starts in `text`, overlapping ones included.
inline std::size_t occurrences(const std::string& text, const std::string& part) {
  std::size_t n = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) {
    ++n;
  }
  return n;
}

}  // namespace fragsim::test
