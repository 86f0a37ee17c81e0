// libFuzzer target: sensor_msgs/PointCloud2 -> the core's xyz cloud (vdc::toXyzCloud), which
// every cloud the estimator receives and every occluder of a next-best-view request goes
// through. Arbitrary fields, offsets, datatypes, point_step, row_step, width x height against the
// data's size and either byte order. A refused cloud must throw vdc::Error; an accepted one
// must hold width x height points whose coordinates are the message's bytes in its byte order.

#include <fuzzer/FuzzedDataProvider.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "fuzzed_messages.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/ros/cloud_conversions.h"

namespace {

// A broken promise: say which, for the crash report, and abort (libFuzzer keeps the input).
[[noreturn]] void fail(const sensor_msgs::PointCloud2& msg, const char* what) {
  std::fprintf(stderr,
               "toXyzCloud accepted a %u x %u cloud (point_step %u, row_step %u, %zu bytes, %s, "
               "fields",
               msg.width, msg.height, msg.point_step, msg.row_step, msg.data.size(),
               msg.is_bigendian ? "big-endian" : "little-endian");
  for (const auto& field : msg.fields) {
    std::fprintf(stderr, " '%s' at %u (datatype %d, count %u)", field.name.c_str(), field.offset,
                 int(field.datatype), field.count);
  }
  std::fprintf(stderr, ") but %s\n", what);
  std::abort();
}

// The float at `at` of the message's data, in the message's byte order.
float floatAt(const sensor_msgs::PointCloud2& msg, std::size_t at) {
  std::uint8_t raw[sizeof(float)];
  std::memcpy(raw, &msg.data[at], sizeof(float));
  if (msg.is_bigendian) std::swap(raw[0], raw[3]), std::swap(raw[1], raw[2]);
  float value;
  std::memcpy(&value, raw, sizeof(float));
  return value;
}

std::uint32_t offsetOf(const sensor_msgs::PointCloud2& msg, const char* name) {
  for (const auto& field : msg.fields) {
    if (field.name == name) return field.offset;
  }
  fail(msg, "it has no such field");
}

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof(float)) == 0; }

void checkCoordinates(const sensor_msgs::PointCloud2& msg,
                      const pcl::PointCloud<pcl::PointXYZ>& cloud) {
  if (cloud.width != msg.width || cloud.height != msg.height ||
      cloud.size() != std::size_t(msg.width) * msg.height) {
    fail(msg, "the core's cloud has another shape");
  }
  if (cloud.empty()) return;
  const std::uint32_t offsets[3] = {offsetOf(msg, "x"), offsetOf(msg, "y"), offsetOf(msg, "z")};
  for (std::uint32_t row = 0; row < msg.height; ++row) {
    for (std::uint32_t column = 0; column < msg.width; ++column) {
      const pcl::PointXYZ& point = cloud[std::size_t(row) * msg.width + column];
      const std::size_t start =
          std::size_t(row) * msg.row_step + std::size_t(column) * msg.point_step;
      for (int k = 0; k < 3; ++k) {
        if (!sameBits(point.data[k], floatAt(msg, start + offsets[k]))) {
          fail(msg, "a coordinate differs from the message's");
        }
      }
    }
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* bytes, std::size_t size) {
  FuzzedDataProvider data(bytes, size);
  const sensor_msgs::PointCloud2 msg = vdc::fuzz::fuzzedPointCloud2(data);
  try {
    checkCoordinates(msg, vdc::toXyzCloud(msg));
  } catch (const vdc::Error&) {
    // refused with a message: what a node logs
  }
  return 0;
}
