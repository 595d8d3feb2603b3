// The one door for input files: the whole text, a leading UTF-8 byte-order mark dropped (and only
// a leading one), and every path that is not a readable file named in one line.

#include "io/input_file.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "io/input_error.hpp"

namespace fragsim {
namespace {

namespace fs = std::filesystem;

const std::string kMark = "\xEF\xBB\xBF";

// `bytes` in a file of the test's temporary folder; returns its path.
std::string file_with(const std::string& name, const std::string& bytes) {
  const fs::path p = fs::path(::testing::TempDir()) / name;
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out << bytes;
  return p.string();
}

std::string error_of(const std::string& path) {
  try {
    read_input_file(path, "probe file");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(InputFile, ReadsEveryByteButALeadingByteOrderMark) {
  const std::string text = "a = 1\r\nb = \xc2\xb0\n";  // CRLF and UTF-8 kept as they are
  EXPECT_EQ(read_input_file(file_with("fragsim_plain.txt", text), "probe file"), text);
  EXPECT_EQ(read_input_file(file_with("fragsim_marked.txt", kMark + text), "probe file"), text);
  // A mark further in is text, and a cut-short mark is not a mark.
  EXPECT_EQ(read_input_file(file_with("fragsim_inner.txt", "x" + kMark), "probe file"),
            "x" + kMark);
  EXPECT_EQ(read_input_file(file_with("fragsim_short.txt", "\xEF\xBB"), "probe file"), "\xEF\xBB");
  EXPECT_EQ(read_input_file(file_with("fragsim_only_mark.txt", kMark), "probe file"), "");
  EXPECT_EQ(read_input_file(file_with("fragsim_empty.txt", ""), "probe file"), "");
}

TEST(InputFile, WhatIsNotAReadableFileIsOneLineNamingThePathAndTheKind) {
  const std::string missing = (fs::path(::testing::TempDir()) / "fragsim_absent.ini").string();
  fs::remove(missing);
  EXPECT_EQ(error_of(missing), missing + ": no such probe file");
  const fs::path dir = fs::path(::testing::TempDir()) / "fragsim_input_dir";
  fs::create_directories(dir);
  EXPECT_EQ(error_of(dir.string()), dir.string() + ": is a directory, not a probe file");
  // A device could be endless: only regular files are read.
  EXPECT_EQ(error_of("/dev/null"), "/dev/null: not a regular file, not a probe file");
}

// The tool's own text files saved with Windows line ends read as if saved with "\n" (a merge
// slice so saved said "rows='4\r' is not a whole number"); a lone '\r' is text.
TEST(InputFile, TextFilesReadCrlfAsLf) {
  const std::string path = file_with("fragsim_crlf.txt", kMark + "a = 1\r\nb = 2\r\nc\rd\r\n");
  EXPECT_EQ(read_text_file(path, "probe file"), "a = 1\nb = 2\nc\rd\n");
  EXPECT_EQ(without_carriage_returns("\r\n\r\r\n"), "\n\r\n");
  EXPECT_EQ(without_carriage_returns("x\r"), "x\r");
}

}  // namespace
}  // namespace fragsim
