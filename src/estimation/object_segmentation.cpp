#include "view_direction_classification/estimation/object_segmentation.h"

#include <pcl/ModelCoefficients.h>
#include <pcl/PointIndices.h>
#include <pcl/filters/extract_indices.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/extract_clusters.h>
#include <pcl/segmentation/sac_segmentation.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

bool isFinitePoint(const pcl::PointXYZ& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

pcl::PointCloud<pcl::PointXYZ> finitePointsWithin(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                                  const Eigen::Vector3d& centre, double radius,
                                                  bool use_region) {
  pcl::PointCloud<pcl::PointXYZ> kept;
  kept.header = cloud.header;
  kept.reserve(cloud.size());
  const Eigen::Vector3f c = centre.cast<float>();
  const float r2 = static_cast<float>(radius * radius);
  for (const pcl::PointXYZ& p : cloud.points) {
    if (!isFinitePoint(p)) continue;
    if (use_region && (p.getVector3fMap() - c).squaredNorm() > r2) continue;
    kept.push_back(p);
  }
  kept.width = static_cast<std::uint32_t>(kept.size());
  kept.height = 1;
  kept.is_dense = true;
  return kept;
}

// Removes the dominant plane (a table or shelf under the object) when RANSAC finds one that
// holds a large enough share of the region: small planes are faces of the object itself.
pcl::PointCloud<pcl::PointXYZ> withoutDominantPlane(const pcl::PointCloud<pcl::PointXYZ>& region,
                                                    const SegmentationParameters& parameters) {
  if (region.size() < 3) return region;
  pcl::SACSegmentation<pcl::PointXYZ> ransac;  // deterministic: PCL seeds its RNG with a constant
  ransac.setModelType(pcl::SACMODEL_PLANE);
  ransac.setMethodType(pcl::SAC_RANSAC);
  ransac.setDistanceThreshold(parameters.plane_distance);
  ransac.setMaxIterations(200);
  ransac.setOptimizeCoefficients(false);
  const auto input = region.makeShared();
  ransac.setInputCloud(input);
  pcl::PointIndices::Ptr inliers(new pcl::PointIndices);
  pcl::ModelCoefficients coefficients;
  ransac.segment(*inliers, coefficients);
  if (static_cast<double>(inliers->indices.size()) <
      parameters.min_plane_fraction * static_cast<double>(region.size())) {
    return region;
  }
  pcl::ExtractIndices<pcl::PointXYZ> extract;
  extract.setInputCloud(input);
  extract.setIndices(inliers);
  extract.setNegative(true);
  pcl::PointCloud<pcl::PointXYZ> rest;
  extract.filter(rest);
  rest.is_dense = true;
  return rest;
}

pcl::PointCloud<pcl::PointXYZ> largestCluster(const pcl::PointCloud<pcl::PointXYZ>& points,
                                              const SegmentationParameters& parameters) {
  pcl::PointCloud<pcl::PointXYZ> empty;
  empty.header = points.header;
  if (points.size() < static_cast<std::size_t>(parameters.min_cluster_points)) return empty;
  const auto input = points.makeShared();
  pcl::search::KdTree<pcl::PointXYZ>::Ptr tree(new pcl::search::KdTree<pcl::PointXYZ>);
  tree->setInputCloud(input);
  pcl::EuclideanClusterExtraction<pcl::PointXYZ> clustering;
  clustering.setClusterTolerance(parameters.cluster_tolerance);
  clustering.setMinClusterSize(parameters.min_cluster_points);
  clustering.setMaxClusterSize(std::numeric_limits<int>::max());
  clustering.setSearchMethod(tree);
  clustering.setInputCloud(input);
  std::vector<pcl::PointIndices> clusters;
  clustering.extract(clusters);  // sorted by size, largest first
  if (clusters.empty()) return empty;
  pcl::PointCloud<pcl::PointXYZ> object(points, clusters.front().indices);
  object.header = points.header;
  object.is_dense = true;
  return object;
}

}  // namespace

void checkSegmentationParameters(const SegmentationParameters& p) {
  if (!p.roi_centre.allFinite()) throw Error("segmentation: roi_centre must be finite");
  if (!(p.roi_radius > 0.0) || !std::isfinite(p.roi_radius)) {
    throw Error("segmentation: roi_radius must be a positive length, got " +
                std::to_string(p.roi_radius));
  }
  if (!(p.plane_distance > 0.0) || !std::isfinite(p.plane_distance)) {
    throw Error("segmentation: plane_distance must be a positive length, got " +
                std::to_string(p.plane_distance));
  }
  if (!(p.min_plane_fraction >= 0.0 && p.min_plane_fraction <= 1.0)) {
    throw Error("segmentation: min_plane_fraction must lie in [0, 1], got " +
                std::to_string(p.min_plane_fraction));
  }
  if (!(p.cluster_tolerance > 0.0) || !std::isfinite(p.cluster_tolerance)) {
    throw Error("segmentation: cluster_tolerance must be a positive length, got " +
                std::to_string(p.cluster_tolerance));
  }
  if (p.min_cluster_points < 1) {
    throw Error("segmentation: min_cluster_points must be at least 1, got " +
                std::to_string(p.min_cluster_points));
  }
}

pcl::PointCloud<pcl::PointXYZ> segmentObject(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                             const SegmentationParameters& parameters) {
  checkSegmentationParameters(parameters);
  if (parameters.mode == SegmentationMode::kNone) {
    return finitePointsWithin(cloud, parameters.roi_centre, parameters.roi_radius, false);
  }
  const pcl::PointCloud<pcl::PointXYZ> region =
      finitePointsWithin(cloud, parameters.roi_centre, parameters.roi_radius, true);
  return largestCluster(withoutDominantPlane(region, parameters), parameters);
}

}  // namespace vdc
