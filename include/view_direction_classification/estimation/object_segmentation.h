#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

#include "view_direction_classification/estimation/tabletop_segmentation.h"

namespace vdc {

// How the object's points are picked out of a depth cloud before features are computed
// (the estimator's `segmentation` parameter).
enum class SegmentationMode {
  kNone,              // the whole cloud is the object (e.g. already segmented upstream)
  kRegionOfInterest,  // a ball around a known point, dominant plane removed, largest cluster kept
  kTabletop,          // the table removed, the cluster standing on it that fits the model's size
  // Every object candidate of the scene, identified against the model(s) and verified against
  // the whole scene: the scene layer's (recognition/scene_estimator.h), which gives each
  // instance's estimator `kNone`; one OrientationEstimator refuses it.
  kScene,
  // As kScene, with the candidates from a detector's instance label image instead of the
  // geometric segmentation (scene/label_segmentation.h); the scene layer's too.
  kLabels,
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
  // Tabletop: a cluster fits the model when its largest extent lies within
  // [(1 - extent_tolerance) x the model's smallest size, (1 + extent_tolerance) x its diagonal].
  double extent_tolerance = 0.15;
  // [px] In an organised cloud, an object with a point this close to the image's edge is cut off
  // by it (its features would describe a part the training never saw): the view is skipped.
  int border_margin = 2;
};

// Throws vdc::Error naming the first bad parameter (non-positive radius or tolerance, fraction
// outside [0, 1], non-finite centre, min_cluster_points < 1, negative border margin).
void checkSegmentationParameters(const SegmentationParameters& parameters);

// What segmentation knows besides the cloud: the model's size (tabletop needs it) and where the
// object was last seen (cloud frame; tabletop then takes the fitting cluster nearest to it).
struct SegmentationContext {
  std::optional<ObjectExtent> extent;
  std::optional<Eigen::Vector3d> expected_centroid;
};

// The object's points in one cloud.
struct ObjectSegment {
  pcl::PointCloud<pcl::PointXYZ> points;  // finite points only, unorganised, is_dense = true
  std::vector<int> indices;               // of those points in the input cloud
  // The table under the object (tabletop), cloud frame: n . x + d = 0, unit n towards the camera.
  std::optional<Eigen::Vector4d> table;
  // Why no usable object was found (nothing on the table, no cluster fits the model, the object
  // is cut by the image border); empty otherwise. Modes none and region_of_interest leave it
  // empty for an empty result: the caller judges the point count.
  std::string failure;
};

// Never throws for cloud content (empty, all-NaN, out-of-region clouds give an empty segment);
// throws vdc::Error for invalid parameters (checkSegmentationParameters) or tabletop without an
// extent.
ObjectSegment segmentObject(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                            const SegmentationParameters& parameters,
                            const SegmentationContext& context = {});

// "none", "region_of_interest", "tabletop"; parseSegmentationMode throws vdc::Error naming the
// accepted ones.
SegmentationMode parseSegmentationMode(const std::string& name);
std::string segmentationModeName(SegmentationMode mode);

}  // namespace vdc
