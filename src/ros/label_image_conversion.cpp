#include "view_direction_classification/ros/label_image_conversion.h"

#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

// How one pixel of a supported encoding is stored.
struct PixelFormat {
  std::size_t bytes = 0;
  bool is_signed = false;
};

PixelFormat formatOf(const std::string& encoding) {
  if (encoding == "mono8" || encoding == "8UC1") return {1, false};
  if (encoding == "mono16" || encoding == "16UC1") return {2, false};
  if (encoding == "32SC1") return {4, true};
  throw Error("The label image's encoding is '" + encoding +
              "'; a label image must be mono8, 8UC1, mono16, 16UC1 or 32SC1 (one channel of "
              "instance ids).");
}

// The pixel at `bytes` as a label: in the message's byte order (the hosts this runs on are
// little-endian); a negative 32SC1 value is background.
std::uint32_t readLabel(const std::uint8_t* bytes, PixelFormat format, bool big_endian) {
  if (format.bytes == 1) return bytes[0];
  if (format.bytes == 2) {
    std::uint16_t value;
    std::memcpy(&value, bytes, sizeof(value));
    return big_endian ? __builtin_bswap16(value) : value;
  }
  std::uint32_t bits;
  std::memcpy(&bits, bytes, sizeof(bits));
  if (big_endian) bits = __builtin_bswap32(bits);
  std::int32_t value;
  std::memcpy(&value, &bits, sizeof(value));
  return value < 0 ? 0u : static_cast<std::uint32_t>(value);
}

}  // namespace

LabelImage toLabelImage(const sensor_msgs::Image& msg) {
  const PixelFormat format = formatOf(msg.encoding);
  // 64-bit sizes: width x bytes or height x step cannot wrap around.
  const std::uint64_t width = msg.width, height = msg.height, step = msg.step;
  constexpr std::uint64_t kMaxSide = std::numeric_limits<int>::max();
  if (width > kMaxSide || height > kMaxSide || step < width * format.bytes ||
      msg.data.size() < height * step) {
    std::ostringstream message;
    message << "The label image is inconsistent: " << width << " x " << height << " pixels of "
            << format.bytes << " byte(s) (" << msg.encoding << "), step " << step << ", but "
            << msg.data.size() << " bytes of data (at least height x step are needed, and step "
            << "at least width x bytes per pixel).";
    throw Error(message.str());
  }
  LabelImage labels;
  labels.width = static_cast<int>(width);
  labels.height = static_cast<int>(height);
  if (width == 0 || height == 0) return labels;  // without walking 2e9 rows of no pixels
  labels.labels.resize(width * height);
  for (std::uint64_t row = 0; row < height; ++row) {
    const std::uint8_t* pixels = &msg.data[row * step];
    for (std::uint64_t column = 0; column < width; ++column) {
      labels.labels[row * width + column] =
          readLabel(pixels + column * format.bytes, format, msg.is_bigendian != 0);
    }
  }
  return labels;
}

}  // namespace vdc
