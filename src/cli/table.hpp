#pragma once
// A plain text table with aligned columns, for the terminal (laid out by
// report/text_table.hpp, so every command's table looks like the comparison's).

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

// io/number_format.hpp's fixed_text, the text the comparison table and the HTML page print.
std::string fixed(double v, int decimals);

}  // namespace fragsim::cli
