#include "view_direction_classification/bop/bop_depth.h"

#include <png.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};

std::string sizeText(int width, int height) {
  return std::to_string(width) + " x " + std::to_string(height);
}

}  // namespace

BopDepthImage readBopDepthPng(const std::string& path, int expected_width, int expected_height) {
  png_image reader{};
  reader.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_file(&reader, path.c_str())) {
    throw Error("cannot read depth image " + path + ": " + reader.message);
  }
  // The simplified API would convert any PNG to 16-bit gray; a depth image that is colour, has
  // alpha or 8 bits was written by something else, and its values are no depths.
  const bool gray16 = (reader.format & PNG_FORMAT_FLAG_COLOR) == 0 &&
                      (reader.format & PNG_FORMAT_FLAG_ALPHA) == 0 &&
                      (reader.format & PNG_FORMAT_FLAG_LINEAR) != 0 &&
                      (reader.format & PNG_FORMAT_FLAG_COLORMAP) == 0;
  if (!gray16) {
    png_image_free(&reader);
    throw Error("depth image " + path + " is not a 16-bit single-channel PNG");
  }
  const int width = static_cast<int>(reader.width), height = static_cast<int>(reader.height);
  if (width != expected_width || height != expected_height) {
    png_image_free(&reader);
    throw Error("depth image " + path + " is " + sizeText(width, height) + ", the camera's " +
                sizeText(expected_width, expected_height));
  }
  BopDepthImage image{width, height, {}};
  image.values.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  reader.format = PNG_FORMAT_LINEAR_Y;
  if (!png_image_finish_read(&reader, nullptr, image.values.data(), 0, nullptr)) {
    throw Error("cannot read depth image " + path + ": " + reader.message);
  }
  return image;
}

void writeBopDepthPng(const BopDepthImage& image, const std::string& path) {
  if (image.width < 1 || image.height < 1 ||
      image.values.size() != static_cast<std::size_t>(image.width) * image.height) {
    throw Error("cannot write depth image " + path + ": its size does not match its values");
  }
  std::unique_ptr<std::FILE, FileCloser> file(std::fopen(path.c_str(), "wb"));
  if (!file) throw Error("cannot write depth image " + path);
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!png || !info) {
    png_destroy_write_struct(&png, &info);
    throw Error("cannot write depth image " + path + ": out of memory");
  }
  // libpng reports errors by longjmp; nothing with a destructor lives between here and the end.
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw Error("cannot write depth image " + path + ": libpng failed");
  }
  png_init_io(png, file.get());
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width),
               static_cast<png_uint_32>(image.height), 16, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  // PNG stores 16-bit samples big-endian; the values are host order.
  png_set_swap(png);
  for (int y = 0; y < image.height; ++y) {
    png_write_row(png, reinterpret_cast<png_const_bytep>(
                           image.values.data() + static_cast<std::size_t>(y) * image.width));
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
}

BopDepthImage quantiseDepth(const std::vector<float>& depth_m, int width, int height,
                            double depth_scale) {
  if (!(depth_scale > 0.0)) throw Error("depth_scale must be > 0");
  if (depth_m.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {
    throw Error("depth image has " + std::to_string(depth_m.size()) + " values, not " +
                sizeText(width, height));
  }
  BopDepthImage image{width, height, std::vector<std::uint16_t>(depth_m.size(), 0)};
  for (std::size_t i = 0; i < depth_m.size(); ++i) {
    const double value = std::round(static_cast<double>(depth_m[i]) * 1000.0 / depth_scale);
    if (value >= 1.0 && value <= std::numeric_limits<std::uint16_t>::max()) {
      image.values[i] = static_cast<std::uint16_t>(value);
    }
  }
  return image;
}

pcl::PointCloud<pcl::PointXYZ> bopDepthCloud(const BopDepthImage& image, const BopCamera& camera) {
  const CameraIntrinsics& k = camera.intrinsics;
  if (image.width != k.width || image.height != k.height) {
    throw Error("depth image is " + sizeText(image.width, image.height) + ", the camera's " +
                sizeText(k.width, k.height));
  }
  const float nan = std::numeric_limits<float>::quiet_NaN();
  pcl::PointCloud<pcl::PointXYZ> cloud(static_cast<std::uint32_t>(k.width),
                                       static_cast<std::uint32_t>(k.height),
                                       pcl::PointXYZ(nan, nan, nan));
  cloud.is_dense = false;
  for (int v = 0; v < k.height; ++v) {
    for (int u = 0; u < k.width; ++u) {
      const std::uint16_t value = image.values[static_cast<std::size_t>(v) * k.width + u];
      if (value == 0) continue;
      const double z = value * camera.depth_scale / 1000.0;
      cloud.at(u, v) =
          pcl::PointXYZ(static_cast<float>((u - k.cx) * z / k.fx),
                        static_cast<float>((v - k.cy) * z / k.fy), static_cast<float>(z));
    }
  }
  return cloud;
}

}  // namespace vdc
