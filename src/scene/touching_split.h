#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <vector>

#include "view_direction_classification/scene/scene_segmentation.h"

namespace vdc::scene {

// The objects in one cluster (indices into the cloud): its convex parts separated at concave
// edges, parts smaller than parameters.min_part_fraction of the cluster (or min_cluster_points)
// joined to the part nearest to them. One part (the cluster itself) when nothing separates.
std::vector<std::vector<int>> splitTouching(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                            const std::vector<int>& cluster,
                                            const SceneSegmentationParameters& parameters);

}  // namespace vdc::scene
