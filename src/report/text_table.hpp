#pragma once
// A plain-text table with aligned columns, as the terminal shows it: the header, a rule of dashes
// under each column, then the rows. The first column (a name) is left-aligned, the others (numbers)
// right-aligned, two spaces apart.

#include <string>
#include <vector>

namespace fragsim {

std::string aligned_text_table(const std::vector<std::string>& headers,
                               const std::vector<std::vector<std::string>>& rows);

}  // namespace fragsim
