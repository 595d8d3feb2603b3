#pragma once
// An 8-bit RGB image, rows from the top, and its PNG form (libpng). PNG files are written whole or
// not at all (through AtomicFile) and are the same bytes for the same pixels.

#include <cassert>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace fragsim {

struct Rgb {
  std::uint8_t r = 0;
  std::uint8_t g = 0;
  std::uint8_t b = 0;
  friend bool operator==(const Rgb&, const Rgb&) = default;
};

class Image {
 public:
  Image() = default;
  Image(int width_px, int height_px, Rgb fill = {});

  int width() const { return width_; }
  int height() const { return height_; }
  bool contains(int x, int y) const { return x >= 0 && y >= 0 && x < width_ && y < height_; }

  // Pixel (x, y) is column x from the left, row y from the top. Asserts it lies in the image.
  Rgb at(int x, int y) const {
    assert(contains(x, y));
    const std::uint8_t* p = bytes_.data() + offset(x, y);
    return {p[0], p[1], p[2]};
  }
  void set(int x, int y, Rgb c) {
    assert(contains(x, y));
    std::uint8_t* p = bytes_.data() + offset(x, y);
    p[0] = c.r;
    p[1] = c.g;
    p[2] = c.b;
  }
  void fill(Rgb c);
  // Fills columns [x0, x1) of rows [y0, y1), clipped to the image.
  void fill_rect(int x0, int y0, int x1, int y1, Rgb c);
  // Copies `src` with its top-left corner at (x, y), clipped to the image.
  void blit(const Image& src, int x, int y);

  // RGB triples, row-major from the top row, 3 * width bytes per row.
  const std::vector<std::uint8_t>& bytes() const { return bytes_; }
  std::uint8_t* data() { return bytes_.data(); }

 private:
  std::size_t offset(int x, int y) const {
    return 3 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
                static_cast<std::size_t>(x));
  }

  int width_ = 0;
  int height_ = 0;
  std::vector<std::uint8_t> bytes_;
};

// The image as a PNG file's bytes (8-bit RGB, no time stamp, so the same pixels give the same
// bytes). Throws std::runtime_error with libpng's message.
std::string encode_png(const Image& image);
// A PNG file's bytes back to 8-bit RGB (any PNG is converted). Throws std::runtime_error.
Image decode_png(const std::string& png_bytes);

// Writes `image` as a PNG file through AtomicFile (whole or not at all); throws naming the path.
void write_png(const std::string& path, const Image& image);
// Reads a PNG file; throws std::runtime_error naming the path.
Image read_png(const std::string& path);

}  // namespace fragsim
