// Text from a mesh file quoted in a message: one line, printable, cut.
#include "debris/mesh_message.hpp"

#include <gtest/gtest.h>

#include <string>

namespace fragsim {
namespace {

TEST(MeshMessage, OneLineJoinsLinesAndDropsTheTrailingBreak) {
  EXPECT_EQ(one_line("bad face\nat line 3\r\n"), "bad face at line 3");
}

TEST(MeshMessage, ShownMakesControlCharactersVisibleAndCuts) {
  EXPECT_EQ(shown(std::string("a\tb\x7f"
                              "c",
                              5),
                  40),
            "a?b?c");
  EXPECT_EQ(shown("abcdef", 4), "abcd...");
  EXPECT_EQ(shown("abcd", 4), "abcd");
}

}  // namespace
}  // namespace fragsim
