#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>

#include <vector>

#include "view_direction_classification/estimation/object_segmentation.h"

namespace vdc {

// What refinement verifies a view's poses against besides the object's own points
// (RefinementView::scene, doc/method.md "Refinement"): the cloud's finite points that can hide
// part of the object, so that a part hidden by another object does not count against the right
// pose. The table under the object is left out: a pose sunk into the table is hidden by nothing,
// and it must still count as a surface where the camera saw the table. Null with segmentation
// `none` (the cloud is the object: nothing else to hide it) or when nothing but the object is
// left.
pcl::PointCloud<pcl::PointXYZ>::ConstPtr verificationScene(
    const pcl::PointCloud<pcl::PointXYZ>& cloud, const ObjectSegment& object,
    const SegmentationParameters& segmentation);

// The same for a whole scene with several support planes (n . x + d = 0, unit n towards the
// camera): every finite point farther than plane_distance from each of them.
pcl::PointCloud<pcl::PointXYZ>::ConstPtr verificationScene(
    const pcl::PointCloud<pcl::PointXYZ>& cloud, const std::vector<Eigen::Vector4d>& supports,
    double plane_distance);

}  // namespace vdc
