#include "view_direction_classification/estimation/object_segmentation.h"

#include <pcl/PointIndices.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/extract_clusters.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/geometry/measured_point.h"

namespace vdc {
namespace {

// The measured points (within `radius` of `centre` when radius > 0) and their indices.
ObjectSegment measuredPointsWithin(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                   const Eigen::Vector3d& centre, double radius) {
  ObjectSegment kept;
  kept.points.header = cloud.header;
  kept.points.reserve(cloud.size());
  const Eigen::Vector3f c = centre.cast<float>();
  const float r2 = static_cast<float>(radius * radius);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const pcl::PointXYZ& p = cloud[i];
    if (!isMeasuredPoint(p)) continue;
    if (radius > 0.0 && (p.getVector3fMap() - c).squaredNorm() > r2) continue;
    kept.points.push_back(p);
    kept.indices.push_back(static_cast<int>(i));
  }
  kept.points.width = static_cast<std::uint32_t>(kept.points.size());
  kept.points.height = 1;
  kept.points.is_dense = true;
  return kept;
}

// The points of `segment` at `subset` (indices into segment.points), indices kept into the
// original cloud.
ObjectSegment subsetOf(const ObjectSegment& segment, const std::vector<int>& subset) {
  ObjectSegment result;
  result.points.header = segment.points.header;
  result.table = segment.table;
  for (const int k : subset) {
    result.points.push_back(segment.points[k]);
    result.indices.push_back(segment.indices[static_cast<std::size_t>(k)]);
  }
  result.points.width = static_cast<std::uint32_t>(result.points.size());
  result.points.height = 1;
  result.points.is_dense = true;
  return result;
}

// Region of interest: the dominant plane (when it holds a large enough share of the region:
// small planes are faces of the object itself) removed, the largest cluster kept.
ObjectSegment largestClusterInRegion(const ObjectSegment& region,
                                     const SegmentationParameters& parameters) {
  std::vector<int> rest;
  const std::optional<Eigen::Vector4d> plane =
      findDominantPlane(region.points, parameters.plane_distance, parameters.min_plane_fraction);
  for (int i = 0; i < static_cast<int>(region.points.size()); ++i) {
    const Eigen::Vector3d p = region.points[i].getVector3fMap().cast<double>();
    if (plane && std::abs(plane->head<3>().dot(p) + (*plane)(3)) <= parameters.plane_distance) {
      continue;
    }
    rest.push_back(i);
  }
  ObjectSegment empty;
  empty.points.header = region.points.header;
  if (rest.size() < static_cast<std::size_t>(parameters.min_cluster_points)) return empty;
  const auto input = region.points.makeShared();
  const pcl::IndicesPtr indices(new std::vector<int>(rest));
  pcl::search::KdTree<pcl::PointXYZ>::Ptr tree(new pcl::search::KdTree<pcl::PointXYZ>);
  tree->setInputCloud(input, indices);
  pcl::EuclideanClusterExtraction<pcl::PointXYZ> clustering;
  clustering.setClusterTolerance(parameters.cluster_tolerance);
  clustering.setMinClusterSize(parameters.min_cluster_points);
  clustering.setMaxClusterSize(std::numeric_limits<int>::max());
  clustering.setSearchMethod(tree);
  clustering.setInputCloud(input);
  clustering.setIndices(indices);
  std::vector<pcl::PointIndices> clusters;
  clustering.extract(clusters);  // sorted by size, largest first
  if (clusters.empty()) return empty;
  ObjectSegment object = subsetOf(region, clusters.front().indices);
  object.table = plane;
  return object;
}

ObjectSegment tabletopObject(const ObjectSegment& finite, const SegmentationParameters& parameters,
                             const SegmentationContext& context) {
  if (!context.extent) throw Error("tabletop segmentation needs the model's extent");
  TabletopParameters tabletop;
  tabletop.plane_distance = parameters.plane_distance;
  tabletop.min_plane_fraction = parameters.min_plane_fraction;
  tabletop.cluster_tolerance = parameters.cluster_tolerance;
  tabletop.min_cluster_points = parameters.min_cluster_points;
  tabletop.extent_tolerance = parameters.extent_tolerance;
  const TabletopResult found =
      segmentTabletop(finite.points, tabletop, *context.extent, context.expected_centroid);
  if (found.chosen < 0) {
    ObjectSegment none;
    none.points.header = finite.points.header;
    none.table = found.table;
    none.failure = found.failure;
    return none;
  }
  ObjectSegment object =
      subsetOf(finite, found.clusters[static_cast<std::size_t>(found.chosen)].indices);
  object.table = found.table;
  return object;
}

// Whether a point of the segment lies within `margin` pixels of an organised cloud's border.
bool touchesImageBorder(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                        const std::vector<int>& indices, int margin) {
  if (cloud.height <= 1) return false;  // unorganised: no image to be cut by
  const int width = static_cast<int>(cloud.width), height = static_cast<int>(cloud.height);
  return std::any_of(indices.begin(), indices.end(), [&](int index) {
    const int row = index / width, column = index % width;
    return row < margin || column < margin || row >= height - margin || column >= width - margin;
  });
}

}  // namespace

void checkSegmentationParameters(const SegmentationParameters& p) {
  if (!p.roi_centre.allFinite()) throw Error("segmentation: roi_centre must be finite");
  auto positive = [](double value, const char* name) {
    if (!(value > 0.0) || !std::isfinite(value)) {
      throw Error(std::string("segmentation: ") + name + " must be a positive length, got " +
                  std::to_string(value));
    }
  };
  positive(p.roi_radius, "roi_radius");
  positive(p.plane_distance, "plane_distance");
  positive(p.cluster_tolerance, "cluster_tolerance");
  if (!(p.min_plane_fraction >= 0.0 && p.min_plane_fraction <= 1.0)) {
    throw Error("segmentation: min_plane_fraction must lie in [0, 1], got " +
                std::to_string(p.min_plane_fraction));
  }
  if (p.min_cluster_points < 1) {
    throw Error("segmentation: min_cluster_points must be at least 1, got " +
                std::to_string(p.min_cluster_points));
  }
  if (!(p.extent_tolerance >= 0.0 && p.extent_tolerance < 1.0)) {
    throw Error("segmentation: extent_tolerance must lie in [0, 1), got " +
                std::to_string(p.extent_tolerance));
  }
  if (p.border_margin < 0) {
    throw Error("segmentation: border_margin must not be negative, got " +
                std::to_string(p.border_margin));
  }
}

ObjectSegment segmentObject(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                            const SegmentationParameters& parameters,
                            const SegmentationContext& context) {
  checkSegmentationParameters(parameters);
  ObjectSegment object;
  switch (parameters.mode) {
    case SegmentationMode::kNone:
      object = measuredPointsWithin(cloud, Eigen::Vector3d::Zero(), 0.0);
      break;
    case SegmentationMode::kRegionOfInterest:
      object = largestClusterInRegion(
          measuredPointsWithin(cloud, parameters.roi_centre, parameters.roi_radius), parameters);
      break;
    case SegmentationMode::kTabletop:
      object = tabletopObject(measuredPointsWithin(cloud, Eigen::Vector3d::Zero(), 0.0), parameters,
                              context);
      break;
    case SegmentationMode::kScene:
    case SegmentationMode::kLabels:
      throw Error("segmentation '" + segmentationModeName(parameters.mode) +
                  "' is the scene layer's (SceneEstimator), not one object's");
  }
  if (object.failure.empty() &&
      touchesImageBorder(cloud, object.indices, parameters.border_margin)) {
    object.failure = "the object touches the image border (cut off by the edge of the view)";
  }
  return object;
}

SegmentationMode parseSegmentationMode(const std::string& name) {
  if (name == "none") return SegmentationMode::kNone;
  if (name == "region_of_interest") return SegmentationMode::kRegionOfInterest;
  if (name == "tabletop") return SegmentationMode::kTabletop;
  if (name == "scene") return SegmentationMode::kScene;
  if (name == "labels") return SegmentationMode::kLabels;
  throw Error("unknown segmentation '" + name +
              "'; expected none, region_of_interest, tabletop, scene or labels");
}

std::string segmentationModeName(SegmentationMode mode) {
  switch (mode) {
    case SegmentationMode::kNone:
      return "none";
    case SegmentationMode::kRegionOfInterest:
      return "region_of_interest";
    case SegmentationMode::kTabletop:
      return "tabletop";
    case SegmentationMode::kScene:
      return "scene";
    case SegmentationMode::kLabels:
      return "labels";
  }
  return "unknown";
}

}  // namespace vdc
