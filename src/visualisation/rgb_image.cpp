#include "view_direction_classification/visualisation/rgb_image.h"

#include <png.h>

#include <cstdio>
#include <memory>
#include <string>

#include "view_direction_classification/common/error.h"

namespace vdc {

RgbImage::RgbImage(int w, int h, const Rgb& fill) : width(w), height(h) {
  if (w <= 0 || h <= 0) throw Error("an image needs a positive size");
  pixels.resize(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3);
  for (std::size_t i = 0; i < pixels.size(); i += 3) {
    pixels[i] = fill[0], pixels[i + 1] = fill[1], pixels[i + 2] = fill[2];
  }
}

namespace {

// The offset of pixel (x, y)'s red byte; throws vdc::Error for a pixel outside the image, which
// would otherwise read or write another row's pixel or past the buffer.
std::size_t pixelOffset(const RgbImage& image, int x, int y) {
  if (x < 0 || y < 0 || x >= image.width || y >= image.height) {
    throw Error("pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the " +
                std::to_string(image.width) + " x " + std::to_string(image.height) + " image");
  }
  return (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) +
          static_cast<std::size_t>(x)) *
         3;
}

}  // namespace

Rgb RgbImage::at(int x, int y) const {
  const std::size_t i = pixelOffset(*this, x, y);
  return {pixels[i], pixels[i + 1], pixels[i + 2]};
}

void RgbImage::set(int x, int y, const Rgb& colour) {
  const std::size_t i = pixelOffset(*this, x, y);
  pixels[i] = colour[0], pixels[i + 1] = colour[1], pixels[i + 2] = colour[2];
}

namespace {
struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
}  // namespace

void writePng(const RgbImage& image, const std::string& path) {
  std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "wb"));
  if (!file) throw Error("cannot write image " + path);
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info) {
    png_destroy_write_struct(&png, &info);
    throw Error("cannot write image " + path + ": out of memory");
  }
  // libpng reports errors by longjmp; nothing with a destructor lives between here and the end.
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw Error("cannot write image " + path + ": libpng failed");
  }
  png_init_io(png, file.get());
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width),
               static_cast<png_uint_32>(image.height), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (int y = 0; y < image.height; ++y) {
    png_write_row(png, const_cast<png_bytep>(image.pixels.data() +
                                             static_cast<std::size_t>(y) * image.width * 3));
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
}

RgbImage readPng(const std::string& path) {
  png_image reader{};
  reader.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&reader, path.c_str())) {
    throw Error("cannot read image " + path + ": " + reader.message);
  }
  reader.format = PNG_FORMAT_RGB;
  RgbImage image(static_cast<int>(reader.width), static_cast<int>(reader.height), {0, 0, 0});
  if (!png_image_finish_read(&reader, nullptr, image.pixels.data(), 0, nullptr)) {
    throw Error("cannot read image " + path + ": " + reader.message);
  }
  return image;
}

}  // namespace vdc
