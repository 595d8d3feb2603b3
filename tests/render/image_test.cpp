// Images and their PNG form: exact round trips, and files written whole or not at all.

#include "render/image.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>
#include <string>

namespace fragsim {
namespace {

namespace fs = std::filesystem;

TEST(Image, EncodesAndDecodesExactly) {
  Image img(7, 3, {10, 20, 30});
  img.set(6, 2, {255, 0, 128});
  const std::string png = encode_png(img);
  ASSERT_GE(png.size(), 8u);
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  const Image back = decode_png(png);
  EXPECT_EQ(back.width(), 7);
  EXPECT_EQ(back.height(), 3);
  EXPECT_EQ(back.bytes(), img.bytes());
  EXPECT_THROW(decode_png("not a png"), std::runtime_error);
  EXPECT_THROW(encode_png(Image()), std::runtime_error);
}

TEST(Image, FileIsWrittenWholeWithoutDebris) {
  const fs::path dir = fs::path(::testing::TempDir()) / "fragsim_png";
  fs::remove_all(dir);
  fs::create_directories(dir);
  Image img(16, 9, {1, 2, 3});
  write_png((dir / "a.png").string(), img);
  EXPECT_EQ(read_png((dir / "a.png").string()).bytes(), img.bytes());
  int files = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1);
  EXPECT_THROW(write_png((dir / "missing" / "a.png").string(), img), std::runtime_error);
}

}  // namespace
}  // namespace fragsim
