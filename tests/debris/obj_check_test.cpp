// The OBJ text check: each input that tinyobjloader read as another shape (a coordinate "nan",
// "inf" or "abc" taken as 0) or misreported (face index -9 as -4) is one line naming file:line and
// the token as written; good files pass.

#include "debris/obj_check.hpp"

#include <gtest/gtest.h>

#include <string>

#include "io/input_error.hpp"

namespace fragsim {
namespace {

std::string error_of(const std::string& text) {
  try {
    check_obj_text(text, "piece.obj");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

const char* kHead = "# a tetrahedron\no T\nv 0 0 0\nv 1 0 0\nv 0 1 0\n";

TEST(ObjCheck, CoordinatesThatAreNotFiniteNumbersNameLineAndToken) {
  for (const char* token : {"nan", "inf", "-inf", "NaN", "infinity"}) {
    EXPECT_EQ(error_of(std::string(kHead) + "v 0 0 " + token + "\nf 1 2 3 4\n"),
              std::string("piece.obj:6: vertex coordinate '") + token + "' is not a finite number");
  }
  for (const char* token : {"abc", "1.2.3", "1,5", "0x1p3", "--1", "1e"}) {
    EXPECT_EQ(error_of(std::string(kHead) + "v 0 0 " + token + "\nf 1 2 3 4\n"),
              std::string("piece.obj:6: vertex coordinate '") + token + "' is not a number");
  }
  EXPECT_EQ(error_of(std::string(kHead) + "v 0 1\nf 1 2 3 4\n"),
            "piece.obj:6: a vertex needs x y z, got 2 numbers");
}

TEST(ObjCheck, FaceIndicesAreReportedAsWritten) {
  // Four vertices before line 7: -9 counts back past the first.
  const std::string four = std::string(kHead) + "v 0 0 1\n";
  EXPECT_EQ(error_of(four + "f -9 -2 -1\n"),
            "piece.obj:7: face index -9 names no vertex: it counts back from the last vertex "
            "before this line, and there are 4");
  EXPECT_EQ(error_of(four + "f 1 2 9\n"),
            "piece.obj:7: face index 9 names no vertex: the file "
            "has 4");
  EXPECT_EQ(error_of(four + "f 0 1 2\n"), "piece.obj:7: face index 0: OBJ counts vertices from 1");
  EXPECT_EQ(error_of(four + "f 1 2 x/1\n"), "piece.obj:7: face index 'x/1' is not a whole number");
}

TEST(ObjCheck, GoodFilesPass) {
  // Signs, exponents, tabs, CRLF and lone CR line ends, vertex colours, texture and normal
  // indices, a comment after the numbers, 1e999 (refused later as a non-finite vertex).
  EXPECT_EQ(error_of("v +1.5 -2e-3\t.5\r\nv 1 2 3 0.5 0.5 0.5\rv 1e999 0 0 # far\n"
                     "vt 0 0\nvn 0 0 1\nf 1/1/1 2//1 -1\n"),
            "");
  // A line of a CR-only file is still found by its number.
  EXPECT_EQ(error_of("v 0 0 0\rv 0 0 abc\r"),
            "piece.obj:2: vertex coordinate 'abc' is not a number");
}

}  // namespace
}  // namespace fragsim
