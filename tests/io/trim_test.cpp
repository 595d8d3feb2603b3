// Blanks around a value are not part of it; blanks inside it are.

#include "io/trim.hpp"

#include <gtest/gtest.h>

namespace fragsim {
namespace {

TEST(Trim, DropsSpacesTabsAndLineEndsAroundTheValueOnly) {
  EXPECT_EQ(trim("  1.5\t"), "1.5");
  EXPECT_EQ(trim("0 1.6 0\r\n"), "0 1.6 0");  // a Windows line end; inner spaces stay
  EXPECT_EQ(trim("\t \r\n"), "");
  EXPECT_EQ(trim(""), "");
  EXPECT_EQ(trim("x"), "x");
}

}  // namespace
}  // namespace fragsim
