#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace vdc {

using Rgb = std::array<std::uint8_t, 3>;

// An 8-bit RGB raster, row-major, origin top left.
struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;  // width * height * 3

  RgbImage() = default;
  // Throws vdc::Error unless w and h are positive.
  RgbImage(int w, int h, const Rgb& fill);
  // Pixel (x, y), x to the right, y down; both throw vdc::Error for a pixel outside the image.
  Rgb at(int x, int y) const;
  void set(int x, int y, const Rgb& colour);
};

// Writes a PNG (libpng). Throws vdc::Error naming the file if it cannot be written.
void writePng(const RgbImage& image, const std::string& path);
// Reads an 8-bit RGB or RGBA PNG (RGBA composed onto black: transparent pixels read black); for
// tests and tools. Throws vdc::Error naming the file.
RgbImage readPng(const std::string& path);

}  // namespace vdc
