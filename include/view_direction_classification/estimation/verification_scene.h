#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>

#include <vector>

#include "view_direction_classification/estimation/object_segmentation.h"
#include "view_direction_classification/refinement/pose_verification.h"

namespace vdc {

// What refinement verifies a view's poses against besides the object's own points
// (RefinementView::scene, doc/method.md "Refinement"): the cloud's finite points that can hide
// part of the object, so that a part hidden by another object does not count against the right
// pose, and apart from them the table's points, where nothing stands hidden: a pose sunk into the
// table, or with a part over the table where the camera saw the table, is contradicted there.
// Empty with segmentation `none` (the cloud is the object: nothing else to hide it) or when
// nothing but the object is left.
SceneDepth verificationScene(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                             const ObjectSegment& object,
                             const SegmentationParameters& segmentation);

// The same for a whole scene with several support planes (n . x + d = 0, unit n towards the
// camera): the points within plane_distance of one of them are supports, the other finite points
// occluders.
SceneDepth verificationScene(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                             const std::vector<Eigen::Vector4d>& supports, double plane_distance);

}  // namespace vdc
