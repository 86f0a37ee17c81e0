#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <sensor_msgs/PointCloud2.h>

namespace vdc {

// The x, y, z coordinates of a sensor_msgs/PointCloud2 (organised or not, any other fields
// ignored; NaN points kept, so an organised cloud keeps its shape; either byte order; a cloud
// without points keeps its width and height). Checked first, because an inconsistent message
// would be read past its buffer: throws vdc::Error naming the problem for a missing x, y or z
// field (the message names which), a field that is not one FLOAT32, a field beyond point_step, or
// a data buffer shorter than height * row_step or a row_step < width * point_step.
pcl::PointCloud<pcl::PointXYZ> toXyzCloud(const sensor_msgs::PointCloud2& msg);

}  // namespace vdc
