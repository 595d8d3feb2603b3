// The terminal's aligned table, on rows worked out by hand: each column as wide as its widest cell,
// the first left-aligned, the others right-aligned, two spaces apart.

#include "report/text_table.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace fragsim {
namespace {

TEST(TextTable, ColumnsAreAsWideAsTheirWidestCell) {
  // Widths: "strategy" and "edge-min" (8), "near" (4), "dev (m)" (7).
  const std::string table = aligned_text_table(
      {"strategy", "near", "dev (m)"}, {{"none", "12", "0.5"}, {"edge-min", "0", "0.0720"}});
  EXPECT_EQ(table,
            "strategy  near  dev (m)\n"
            "--------  ----  -------\n"
            "none        12      0.5\n"
            "edge-min     0   0.0720\n");
}

TEST(TextTable, ShortRowsArePaddedAndExtraCellsDropped) {
  // The header sets the columns: a missing cell prints as blanks, a cell beyond them not at all.
  const std::string table = aligned_text_table({"a", "bb"}, {{"x"}, {"yyy", "1", "extra"}});
  EXPECT_EQ(table,
            "a    bb\n"
            "---  --\n"
            "x      \n"
            "yyy   1\n");
}

TEST(TextTable, NoRowsIsTheHeaderAndItsRule) {
  EXPECT_EQ(aligned_text_table({"name", "n"}, {}), "name  n\n----  -\n");
}

}  // namespace
}  // namespace fragsim
