#include "io/trim.hpp"

namespace fragsim {

std::string trim(const std::string& s) {
  constexpr const char* kBlanks = " \t\r\n";
  const auto b = s.find_first_not_of(kBlanks);
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(kBlanks);
  return s.substr(b, e - b + 1);
}

}  // namespace fragsim
