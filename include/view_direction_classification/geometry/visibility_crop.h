#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <Eigen/Core>
#include <Eigen/Geometry>

#include <vector>

#include "view_direction_classification/geometry/surface_sampling.h"

namespace vdc {

// The occlusion experiment (doc/method.md section 11): keeps only the points of a camera-frame cloud
// within `radius` [m] (inclusive) of at least one anchor. Anchors are given in the object frame
// and moved into the camera frame by camera_from_object. The result has the input's size,
// organisation and header; dropped points become NaN (is_dense = false). Throws vdc::Error for
// no anchors or a non-positive radius.
pcl::PointCloud<pcl::PointXYZ> cropToAnchors(const pcl::PointCloud<pcl::PointXYZ>& camera_cloud,
                                             const Eigen::Isometry3d& camera_from_object,
                                             const std::vector<Eigen::Vector3d>& anchors,
                                             double radius);

// Fraction of the surface set within `radius` (inclusive) of any anchor (object frame): the
// "visible surface fraction" of an occlusion setting. Throws vdc::Error for an empty surface
// set, no anchors or a non-positive radius.
double surfaceFractionNearAnchors(const SurfaceSamples& surface,
                                  const std::vector<Eigen::Vector3d>& anchors, double radius);

}  // namespace vdc
