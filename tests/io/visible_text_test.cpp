// Text from an input quoted into a message: control characters shown as escapes, so a NUL byte
// cannot end the message early (what() is a C string) nor a stray '\r' garble the terminal.

#include "io/visible_text.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <string>

namespace fragsim {
namespace {

TEST(VisibleText, ControlCharactersBecomeEscapes) {
  const std::string with_nul(
      "0.\0"
      "01",
      5);
  EXPECT_EQ(visible_text(with_nul), "0.\\x0001");
  EXPECT_EQ(std::strlen(visible_text(with_nul).c_str()), visible_text(with_nul).size());
  EXPECT_EQ(visible_text("a\tb\r\n\x1b[31m\x7f"), "a\\tb\\r\\n\\x1b[31m\\x7f");
  // Printable text, a backslash and UTF-8 are kept as they are.
  EXPECT_EQ(visible_text("C:\\tracks\\t.csv \xc2\xb0"), "C:\\tracks\\t.csv \xc2\xb0");
}

TEST(VisibleText, LongTextIsCut) {
  EXPECT_EQ(visible_text(std::string(300, 'x')), std::string(200, 'x') + "...");
  EXPECT_EQ(visible_text("abcdef", 3), "abc...");
  EXPECT_EQ(visible_text("abc", 3), "abc");
}

}  // namespace
}  // namespace fragsim
