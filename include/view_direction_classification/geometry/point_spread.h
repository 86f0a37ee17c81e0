#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/types.h>

namespace vdc {

// Whether the points at `indices` (all of them when empty) spread by at least `min_spread` [m]
// (a standard deviation) in two directions: at least 10 of them, not all near one line or one
// spot. RANSAC for a plane or a circle draws only degenerate samples from a set that does not,
// and PCL prints an error line for every such sample: ask before fitting.
bool spreadsInTwoDirections(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                            const pcl::Indices& indices, double min_spread);

}  // namespace vdc
