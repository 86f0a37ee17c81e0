#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include "view_direction_classification/scene/scene_segmentation.h"

namespace vdc::scene {

// Fills the candidate's centroid, principal axes and extent from its (non-empty) indices.
void describeShape(const pcl::PointCloud<pcl::PointXYZ>& cloud, SceneCandidate* candidate);

}  // namespace vdc::scene
