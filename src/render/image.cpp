#include "render/image.hpp"

#include <png.h>

#include <algorithm>
#include <cassert>
#include <cstddef>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "io/atomic_file.hpp"
#include "io/input_file.hpp"

namespace fragsim {

namespace {

// libpng's simplified API reports failures in the image's message, never by longjmp.
png_image blank_png_image() {
  png_image img;
  std::memset(&img, 0, sizeof img);
  img.version = PNG_IMAGE_VERSION;
  return img;
}

}  // namespace

Image::Image(int width_px, int height_px, Rgb fill)
    : width_(std::max(0, width_px)), height_(std::max(0, height_px)) {
  bytes_.resize(offset(0, height_));
  this->fill(fill);
}

void Image::fill(Rgb c) {
  fill_rect(0, 0, width_, height_, c);
}

void Image::fill_rect(int x0, int y0, int x1, int y1, Rgb c) {
  x0 = std::max(x0, 0);
  y0 = std::max(y0, 0);
  x1 = std::min(x1, width_);
  y1 = std::min(y1, height_);
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) set(x, y, c);
  }
}

void Image::blit(const Image& src, int x, int y) {
  const int x0 = std::max(0, -x);
  const int x1 = std::min(src.width(), width_ - x);
  if (x0 >= x1) return;
  for (int row = std::max(0, -y); row < std::min(src.height(), height_ - y); ++row) {
    const std::uint8_t* from = src.bytes_.data() + src.offset(x0, row);
    std::copy(from, from + 3 * (x1 - x0), bytes_.data() + offset(x + x0, y + row));
  }
}

std::string encode_png(const Image& image) {
  if (image.width() <= 0 || image.height() <= 0) {
    throw std::runtime_error("PNG: cannot encode an empty image");
  }
  png_image img = blank_png_image();
  img.width = static_cast<png_uint_32>(image.width());
  img.height = static_cast<png_uint_32>(image.height());
  img.format = PNG_FORMAT_RGB;
  const png_int_32 stride = 3 * image.width();
  const void* pixels = image.bytes().data();
  // Room for the worst case (incompressible rows plus the chunks), so one pass suffices.
  png_alloc_size_t size = PNG_IMAGE_PNG_SIZE_MAX(img);
  std::string out(size, '\0');
  if (!png_image_write_to_memory(&img, out.data(), &size, 0, pixels, stride, nullptr)) {
    const std::string why = img.message;
    png_image_free(&img);
    throw std::runtime_error("PNG: " + why);
  }
  out.resize(size);
  return out;
}

Image decode_png(const std::string& png_bytes) {
  png_image img = blank_png_image();
  if (!png_image_begin_read_from_memory(&img, png_bytes.data(), png_bytes.size())) {
    const std::string why = img.message;
    png_image_free(&img);
    throw std::runtime_error("PNG: " + why);
  }
  img.format = PNG_FORMAT_RGB;
  Image out(static_cast<int>(img.width), static_cast<int>(img.height));
  if (!png_image_finish_read(&img, nullptr, out.data(), 3 * out.width(), nullptr)) {
    const std::string why = img.message;
    png_image_free(&img);
    throw std::runtime_error("PNG: " + why);
  }
  return out;
}

void write_png(const std::string& path, const Image& image) {
  std::string bytes;
  try {
    bytes = encode_png(image);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
  write_file_atomically(path, bytes);
}

Image read_png(const std::string& path) {
  const std::string bytes = read_input_file(path, "PNG file");
  try {
    return decode_png(bytes);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(path + ": " + e.what());
  }
}

}  // namespace fragsim
