#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <vector>

#include "depth_tolerance.h"

namespace vdc::scene {

// Connected components of image neighbours closer than the tolerance at their depth among the
// points whose `standing` entry (support_planes.h) is not kNotStanding; components of at least
// `min_points`.
std::vector<std::vector<int>> organisedClusters(
    const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud, const std::vector<int>& standing,
    const DepthTolerance& tolerance, int min_points);

// Euclidean clusters (neighbours closer than the tolerance at their depth) of the points at
// `indices`; clusters of at least `min_points`, as indices into the cloud.
std::vector<std::vector<int>> euclideanClusters(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                                const std::vector<int>& indices,
                                                const DepthTolerance& tolerance, int min_points);

}  // namespace vdc::scene
