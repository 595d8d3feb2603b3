#include "cli/table.hpp"

#include <algorithm>
#include <cstdio>
#include <iomanip>

namespace fragsim::cli {

void Table::print(std::ostream& out) const {
  std::vector<std::size_t> width(headers_.size(), 0);
  auto measure = [&width](const std::vector<std::string>& row) {
    for (std::size_t i = 0; i < row.size() && i < width.size(); ++i) {
      width[i] = std::max(width[i], row[i].size());
    }
  };
  measure(headers_);
  for (const auto& r : rows_) measure(r);
  auto print_row = [&](const std::vector<std::string>& row) {
    for (std::size_t i = 0; i < width.size(); ++i) {
      const std::string cell = i < row.size() ? row[i] : "";
      if (i > 0) out << "  ";
      if (i == 0) {
        out << std::left << std::setw(static_cast<int>(width[i])) << cell;
      } else {
        out << std::right << std::setw(static_cast<int>(width[i])) << cell;
      }
    }
    out << '\n';
  };
  print_row(headers_);
  std::vector<std::string> rule;
  for (std::size_t w : width) rule.emplace_back(w, '-');
  print_row(rule);
  for (const auto& r : rows_) print_row(r);
}

std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

}  // namespace fragsim::cli
