#include "view_direction_classification/ros/cloud_conversions.h"

#include <pcl_conversions/pcl_conversions.h>

#include <sstream>
#include <string>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

void checkCoordinateField(const sensor_msgs::PointCloud2& msg, const std::string& name) {
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
    return;
  }
  std::string present;
  for (const auto& field : msg.fields) present += (present.empty() ? "" : ", ") + field.name;
  throw Error(cloud + " has no field '" + name + "' (its fields: " +
              (present.empty() ? "none" : present) + "); x, y and z are needed.");
}

}  // namespace

pcl::PointCloud<pcl::PointXYZ> toXyzCloud(const sensor_msgs::PointCloud2& msg) {
  for (const char* name : {"x", "y", "z"}) checkCoordinateField(msg, name);
  const std::size_t width = msg.width, height = msg.height;
  if (std::size_t(msg.row_step) < width * msg.point_step ||
      msg.data.size() < height * msg.row_step) {
    std::ostringstream message;
    message << "The PointCloud2 in frame '" << msg.header.frame_id << "' is inconsistent: " << width
            << " x " << height << " points of " << msg.point_step << " bytes, row_step "
            << msg.row_step << ", but " << msg.data.size() << " bytes of data.";
    throw Error(message.str());
  }
  pcl::PointCloud<pcl::PointXYZ> cloud;
  pcl::fromROSMsg(msg, cloud);
  return cloud;
}

}  // namespace vdc
