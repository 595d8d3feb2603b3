#pragma once
// A plain text table with aligned columns, for the terminal.

#include <ostream>
#include <string>
#include <vector>

namespace fragsim::cli {

class Table {
 public:
  explicit Table(std::vector<std::string> headers) : headers_(std::move(headers)) {}
  void add_row(std::vector<std::string> cells) { rows_.push_back(std::move(cells)); }
  // The first column left-aligned, the others right-aligned (numbers).
  void print(std::ostream& out) const;

 private:
  std::vector<std::string> headers_;
  std::vector<std::vector<std::string>> rows_;
};

std::string fixed(double v, int decimals);

}  // namespace fragsim::cli
