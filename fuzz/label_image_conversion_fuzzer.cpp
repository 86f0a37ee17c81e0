// libFuzzer target: sensor_msgs/Image -> the core's LabelImage (vdc::toLabelImage), which every
// label image of the estimator's segmentation `labels` goes through. Any encoding, width, height
// and step against the data's size, either byte order. A refused image must throw vdc::Error; an
// accepted one must hold width x height labels, each the message's pixel in its byte order (a
// negative 32SC1 pixel: 0).

#include <fuzzer/FuzzedDataProvider.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/ros/label_image_conversion.h"

namespace {

constexpr std::uint32_t kMaxImageBytes = 1 << 16;

// An encoding: often one the conversion reads, else a short string of the bytes.
std::string fuzzedEncoding(FuzzedDataProvider& data) {
  static const char* const kKnown[] = {"mono8", "8UC1", "mono16", "16UC1",
                                       "32SC1", "rgb8", "32FC1"};
  if (data.ConsumeBool()) return kKnown[data.ConsumeIntegralInRange<std::size_t>(0, 6)];
  return data.ConsumeRandomLengthString(12);
}

std::uint32_t bytesOf(const std::string& encoding) {
  if (encoding == "mono16" || encoding == "16UC1") return 2;
  if (encoding == "32SC1") return 4;
  return 1;
}

// Sizes that agree (or nearly: a few bytes of padding or of data more or less), or any.
sensor_msgs::Image fuzzedImage(FuzzedDataProvider& data) {
  sensor_msgs::Image msg;
  msg.encoding = fuzzedEncoding(data);
  msg.is_bigendian = data.ConsumeBool();
  std::uint32_t data_size = 0;
  if (data.ConsumeBool()) {
    msg.width = data.ConsumeIntegralInRange<std::uint32_t>(0, 64);
    msg.height = data.ConsumeIntegralInRange<std::uint32_t>(0, 16);
    msg.step = msg.width * bytesOf(msg.encoding) + data.ConsumeIntegralInRange<std::uint32_t>(0, 4);
    const std::int64_t size =
        std::int64_t(msg.height) * msg.step + data.ConsumeIntegralInRange<std::int64_t>(-4, 4);
    data_size =
        std::uint32_t(std::max<std::int64_t>(0, std::min<std::int64_t>(size, kMaxImageBytes)));
  } else {
    msg.width = data.ConsumeIntegral<std::uint32_t>();
    msg.height = data.ConsumeIntegral<std::uint32_t>();
    msg.step = data.ConsumeIntegral<std::uint32_t>();
    data_size = data.ConsumeIntegralInRange<std::uint32_t>(0, kMaxImageBytes);
  }
  msg.data = data.ConsumeBytes<std::uint8_t>(data_size);
  if (msg.data.size() < data_size && !msg.data.empty()) {
    // Repeat the bytes a short input has: the layout matters more than the values.
    const std::size_t given = msg.data.size();
    msg.data.resize(data_size);
    for (std::size_t i = given; i < data_size; ++i) msg.data[i] = msg.data[i % given];
  }
  return msg;
}

[[noreturn]] void fail(const sensor_msgs::Image& msg, const char* what) {
  std::fprintf(stderr,
               "toLabelImage accepted a %u x %u '%s' image (step %u, %zu bytes, %s) but %s\n",
               msg.width, msg.height, msg.encoding.c_str(), msg.step, msg.data.size(),
               msg.is_bigendian ? "big-endian" : "little-endian", what);
  std::abort();
}

// The pixel as the encoding defines it, read byte by byte (independently of the conversion).
std::uint32_t pixel(const sensor_msgs::Image& msg, std::size_t at, std::uint32_t bytes) {
  std::uint32_t value = 0;
  for (std::uint32_t k = 0; k < bytes; ++k) {
    const std::uint32_t byte = msg.data[at + (msg.is_bigendian ? k : bytes - 1 - k)];
    value = (value << 8) | byte;
  }
  if (bytes == 4 && (value & 0x80000000u) != 0) return 0;  // a negative 32SC1 label
  return value;
}

void checkLabels(const sensor_msgs::Image& msg, const vdc::LabelImage& labels) {
  if (std::uint32_t(labels.width) != msg.width || std::uint32_t(labels.height) != msg.height) {
    fail(msg, "the label image has another shape");
  }
  const std::size_t pixels = std::size_t(msg.width) * msg.height;
  if (labels.labels.size() != pixels) fail(msg, "it holds another number of labels");
  if (pixels == 0) return;  // without walking 2e9 rows of no pixels
  const std::uint32_t bytes = bytesOf(msg.encoding);
  for (std::size_t row = 0; row < msg.height; ++row) {
    for (std::size_t column = 0; column < msg.width; ++column) {
      if (labels.labels[row * msg.width + column] !=
          pixel(msg, row * msg.step + column * bytes, bytes)) {
        fail(msg, "a label differs from the message's pixel");
      }
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  FuzzedDataProvider data(bytes, size);
  const sensor_msgs::Image msg = fuzzedImage(data);
  try {
    checkLabels(msg, vdc::toLabelImage(msg));
  } catch (const vdc::Error&) {
    // refused with a message: what the node logs
  }
  return 0;
}
