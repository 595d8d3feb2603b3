#include "cli/table.hpp"

#include "io/number_format.hpp"
#include "report/text_table.hpp"

namespace fragsim::cli {

void Table::print(std::ostream& out) const {
  out << aligned_text_table(headers_, rows_);
}

std::string fixed(double v, int decimals) {
  return fixed_text(v, decimals);
}

}  // namespace fragsim::cli
