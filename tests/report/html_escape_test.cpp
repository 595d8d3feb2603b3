// Text for HTML and SVG: the five markup characters escaped, everything else as it is.

#include "report/html_escape.hpp"

#include <gtest/gtest.h>

namespace fragsim {
namespace {

TEST(HtmlEscape, EscapesTheFiveMarkupCharacters) {
  EXPECT_EQ(html_escape("<a href=\"x\">Tom & Jerry's</a>"),
            "&lt;a href=&quot;x&quot;&gt;Tom &amp; Jerry&#39;s&lt;/a&gt;");
  EXPECT_EQ(html_escape("plain text, 1.5 m"), "plain text, 1.5 m");
  EXPECT_EQ(html_escape("\xc2\xb0"), "\xc2\xb0");  // UTF-8 passes through
}

}  // namespace
}  // namespace fragsim
