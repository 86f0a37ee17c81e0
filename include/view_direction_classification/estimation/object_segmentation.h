#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>

namespace vdc {

// How the object's points are picked out of a depth cloud before features are computed
// (the estimator's `segmentation` parameter).
enum class SegmentationMode {
  kNone,              // the whole cloud is the object (e.g. already segmented upstream)
  kRegionOfInterest,  // a ball around a known point, dominant plane removed, largest cluster kept
};

struct SegmentationParameters {
  SegmentationMode mode = SegmentationMode::kNone;
  // Region of interest, in the cloud's frame (the shell moves the configured fixed-frame point
  // into the cloud's frame with tf).
  Eigen::Vector3d roi_centre = Eigen::Vector3d::Zero();
  double roi_radius = 0.15;  // [m]
  // The dominant plane (table, shelf) is removed when RANSAC finds one holding at least this
  // fraction of the region's points, with this inlier distance [m].
  double plane_distance = 0.008;
  double min_plane_fraction = 0.15;
  // Euclidean clustering of what is left: tolerance [m] and the smallest cluster kept.
  double cluster_tolerance = 0.01;
  int min_cluster_points = 50;
};

// Throws vdc::Error naming the first bad parameter (non-positive radius or tolerance, fraction
// outside [0, 1], non-finite centre, min_cluster_points < 1).
void checkSegmentationParameters(const SegmentationParameters& parameters);

// The object's points (finite points only, unorganised, is_dense = true); empty when nothing
// is left (an empty, all-NaN or out-of-region cloud). Never throws for cloud content; throws
// vdc::Error for invalid parameters (checkSegmentationParameters).
pcl::PointCloud<pcl::PointXYZ> segmentObject(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                             const SegmentationParameters& parameters);

}  // namespace vdc
