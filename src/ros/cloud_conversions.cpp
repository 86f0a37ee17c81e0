#include "view_direction_classification/ros/cloud_conversions.h"

#include <pcl_conversions/pcl_conversions.h>

#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

// The offset of the coordinate field `name` within a point. Throws vdc::Error if it is missing,
// not one FLOAT32 or does not fit in point_step.
std::uint32_t coordinateOffset(const sensor_msgs::PointCloud2& msg, const std::string& name) {
  const std::string cloud = "The PointCloud2 in frame '" + msg.header.frame_id + "'";
  for (const auto& field : msg.fields) {
    if (field.name != name) continue;
    if (field.datatype != sensor_msgs::PointField::FLOAT32 || field.count != 1) {
      std::ostringstream message;
      message << cloud << " has a field '" << name << "' of datatype " << int(field.datatype)
              << " and count " << field.count << ", but a single FLOAT32 ("
              << int(sensor_msgs::PointField::FLOAT32) << ") is needed.";
      throw Error(message.str());
    }
    if (std::size_t(field.offset) + sizeof(float) > msg.point_step) {
      std::ostringstream message;
      message << cloud << " has its field '" << name << "' at offset " << field.offset
              << ", beyond its point_step of " << msg.point_step << " bytes.";
      throw Error(message.str());
    }
    return field.offset;
  }
  std::string present;
  for (const auto& field : msg.fields) present += (present.empty() ? "" : ", ") + field.name;
  throw Error(cloud + " has no field '" + name + "' (its fields: " +
              (present.empty() ? "none" : present) + "); x, y and z are needed.");
}

// The FLOAT32 at `bytes` in the message's byte order (the hosts this runs on are little-endian).
float readFloat(const std::uint8_t* bytes, bool big_endian) {
  std::uint32_t bits;
  std::memcpy(&bits, bytes, sizeof(bits));
  if (big_endian) bits = __builtin_bswap32(bits);
  float value;
  std::memcpy(&value, &bits, sizeof(value));
  return value;
}

}  // namespace

pcl::PointCloud<pcl::PointXYZ> toXyzCloud(const sensor_msgs::PointCloud2& msg) {
  const std::uint32_t x = coordinateOffset(msg, "x"), y = coordinateOffset(msg, "y"),
                      z = coordinateOffset(msg, "z");
  const std::size_t width = msg.width, height = msg.height;
  if (std::size_t(msg.row_step) < width * msg.point_step ||
      msg.data.size() < height * msg.row_step) {
    std::ostringstream message;
    message << "The PointCloud2 in frame '" << msg.header.frame_id << "' is inconsistent: " << width
            << " x " << height << " points of " << msg.point_step << " bytes, row_step "
            << msg.row_step << ", but " << msg.data.size() << " bytes of data.";
    throw Error(message.str());
  }
  // Read here rather than by pcl::fromROSMsg, which fuzz/cloud_conversion_fuzzer caught three
  // times: it copies a big-endian cloud's bytes unswapped, takes the address of the first point
  // of an empty cloud (undefined behaviour), and (PCL 1.13) merges x at 4 and z at 12 into one
  // 12-byte copy that overwrites a y at 0.
  pcl::PointCloud<pcl::PointXYZ> cloud;
  pcl_conversions::toPCL(msg.header, cloud.header);
  cloud.resize(width * height);
  cloud.width = msg.width;
  cloud.height = msg.height;
  cloud.is_dense = msg.is_dense;
  if (cloud.empty()) return cloud;  // without walking 4e9 rows of no points
  for (std::size_t row = 0; row < height; ++row) {
    for (std::size_t column = 0; column < width; ++column) {
      const std::uint8_t* point = &msg.data[row * msg.row_step + column * msg.point_step];
      pcl::PointXYZ& p = cloud[row * width + column];
      p.x = readFloat(point + x, msg.is_bigendian);
      p.y = readFloat(point + y, msg.is_bigendian);
      p.z = readFloat(point + z, msg.is_bigendian);
    }
  }
  return cloud;
}

}  // namespace vdc
