#include "view_direction_classification/scene/scene_segmentation.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "candidate_shape.h"
#include "far_points.h"
#include "object_clusters.h"
#include "support_planes.h"
#include "touching_split.h"
#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

void require(bool valid, const char* name, double value, const char* requirement) {
  if (valid) return;
  std::ostringstream message;
  message << "scene segmentation parameter " << name << " is " << value << ", it must be "
          << requirement;
  throw Error(message.str());
}

bool positive(double value) { return std::isfinite(value) && value > 0.0; }

std::vector<int> finiteIndices(const pcl::PointCloud<pcl::PointXYZ>& cloud) {
  std::vector<int> finite;
  finite.reserve(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const pcl::PointXYZ& p = cloud[i];
    if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z))
      finite.push_back(static_cast<int>(i));
  }
  return finite;
}

bool largerFirst(const std::vector<int>& a, const std::vector<int>& b) {
  // Ties by the first index, so that the order does not depend on how PCL listed the clusters.
  if (a.size() != b.size()) return a.size() > b.size();
  return a.front() < b.front();
}

// Drops clusters over max_cluster_points and all but the max_candidates largest (the cost of
// splitting and describing them is bounded so), counting and explaining the drops.
void capClusters(std::vector<std::vector<int>>* clusters,
                 const SceneSegmentationParameters& parameters, SceneSegments* result) {
  const std::size_t before = clusters->size();
  clusters->erase(std::remove_if(clusters->begin(), clusters->end(),
                                 [&](const std::vector<int>& cluster) {
                                   return cluster.size() >
                                          static_cast<std::size_t>(parameters.max_cluster_points);
                                 }),
                  clusters->end());
  if (const std::size_t large = before - clusters->size(); large > 0) {
    result->dropped_clusters += static_cast<int>(large);
    result->note += std::to_string(large) + " cluster(s) of more than " +
                    std::to_string(parameters.max_cluster_points) +
                    " points dropped (max_cluster_points: background, not an object); ";
  }
  std::sort(clusters->begin(), clusters->end(), largerFirst);
  if (clusters->size() > static_cast<std::size_t>(parameters.max_candidates)) {
    const std::size_t excess =
        clusters->size() - static_cast<std::size_t>(parameters.max_candidates);
    clusters->resize(static_cast<std::size_t>(parameters.max_candidates));
    result->dropped_clusters += static_cast<int>(excess);
    result->note += std::to_string(excess) + " smallest cluster(s) dropped (max_candidates " +
                    std::to_string(parameters.max_candidates) + "); ";
  }
}

// The candidates of the (capped) clusters: each split into its objects, described, largest first.
std::vector<SceneCandidate> candidatesOf(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                         const std::vector<std::vector<int>>& clusters,
                                         const std::vector<int>& standing,
                                         const SceneSegmentationParameters& parameters) {
  std::vector<SceneCandidate> candidates;
  for (std::size_t k = 0; k < clusters.size(); ++k) {
    std::vector<std::vector<int>> parts = parameters.split_touching
                                              ? scene::splitTouching(cloud, clusters[k], parameters)
                                              : std::vector<std::vector<int>>{clusters[k]};
    for (std::vector<int>& part : parts) {
      if (part.size() < static_cast<std::size_t>(parameters.min_cluster_points)) continue;
      std::sort(part.begin(), part.end());
      SceneCandidate candidate;
      candidate.indices = std::move(part);
      candidate.cluster = static_cast<int>(k);
      candidates.push_back(std::move(candidate));
    }
  }
  std::sort(candidates.begin(), candidates.end(),
            [](const SceneCandidate& a, const SceneCandidate& b) {
              return largerFirst(a.indices, b.indices);
            });
  for (SceneCandidate& candidate : candidates) {
    scene::describeShape(cloud, &candidate);
    candidate.support = scene::supportOf(candidate.indices, standing);
  }
  return candidates;
}

// A shared pointer to the caller's cloud for PCL's interfaces, which take one; it does not own
// the cloud (the caller's outlives this call), so nothing is copied.
pcl::PointCloud<pcl::PointXYZ>::ConstPtr borrowed(const pcl::PointCloud<pcl::PointXYZ>& cloud) {
  return pcl::PointCloud<pcl::PointXYZ>::ConstPtr(&cloud,
                                                  [](const pcl::PointCloud<pcl::PointXYZ>*) {});
}

// The clusters of the points standing on a support (or of all, without one): image neighbours in
// organised clouds, Euclidean neighbours otherwise, both within the tolerance at their depth.
std::vector<std::vector<int>> clustersOf(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                         const std::vector<int>& finite,
                                         const std::vector<int>& standing, bool organised,
                                         const SceneSegmentationParameters& parameters) {
  const scene::DepthTolerance tolerance{parameters.cluster_tolerance,
                                        parameters.depth_tolerance_growth};
  if (organised) {
    return scene::organisedClusters(borrowed(cloud), standing, tolerance,
                                    parameters.min_cluster_points);
  }
  std::vector<int> objects;
  for (const int i : finite) {
    if (standing[static_cast<std::size_t>(i)] != scene::kNotStanding) objects.push_back(i);
  }
  return scene::euclideanClusters(cloud, objects, tolerance, parameters.min_cluster_points);
}

}  // namespace

void checkSceneSegmentationParameters(const SceneSegmentationParameters& p) {
  require(std::isfinite(p.depth_tolerance_growth) && p.depth_tolerance_growth >= 0,
          "depth_tolerance_growth", p.depth_tolerance_growth, "0 or more [m per m^2]");
  require(positive(p.plane_distance), "plane_distance", p.plane_distance, "positive [m]");
  require(p.min_plane_points >= 3, "min_plane_points", p.min_plane_points, "at least 3");
  require(std::isfinite(p.min_plane_width) && p.min_plane_width >= 0, "min_plane_width",
          p.min_plane_width, "0 or more [m]");
  require(positive(p.plane_angle_deg) && p.plane_angle_deg < 90, "plane_angle_deg",
          p.plane_angle_deg, "between 0 and 90 [deg]");
  require(std::isfinite(p.max_support_tilt_deg) && p.max_support_tilt_deg >= 0 &&
              p.max_support_tilt_deg <= 90,
          "max_support_tilt_deg", p.max_support_tilt_deg, "between 0 and 90 [deg]");
  require(p.max_support_planes >= 0, "max_support_planes", p.max_support_planes, "0 or more");
  require(positive(p.max_height_above_plane) && p.max_height_above_plane > p.plane_distance,
          "max_height_above_plane", p.max_height_above_plane,
          "finite and more than plane_distance [m]");
  require(positive(p.cluster_tolerance), "cluster_tolerance", p.cluster_tolerance, "positive [m]");
  require(p.min_cluster_points >= 1, "min_cluster_points", p.min_cluster_points, "at least 1");
  require(p.max_cluster_points >= p.min_cluster_points, "max_cluster_points", p.max_cluster_points,
          "at least min_cluster_points");
  require(p.max_candidates >= 1, "max_candidates", p.max_candidates, "at least 1");
  require(p.label_class_divisor >= 1, "label_class_divisor", p.label_class_divisor, "at least 1");
  require(positive(p.supervoxel_voxel), "supervoxel_voxel", p.supervoxel_voxel, "positive [m]");
  require(positive(p.supervoxel_seed) && p.supervoxel_seed >= p.supervoxel_voxel, "supervoxel_seed",
          p.supervoxel_seed, "finite and at least supervoxel_voxel [m]");
  require(std::isfinite(p.concavity_tolerance_deg) && p.concavity_tolerance_deg >= 0 &&
              p.concavity_tolerance_deg < 180,
          "concavity_tolerance_deg", p.concavity_tolerance_deg, "in [0, 180) [deg]");
  require(
      std::isfinite(p.min_part_fraction) && p.min_part_fraction >= 0 && p.min_part_fraction <= 0.5,
      "min_part_fraction", p.min_part_fraction, "in [0, 0.5]");
}

SceneSegments segmentScene(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                           const SceneSegmentationParameters& parameters) {
  checkSceneSegmentationParameters(parameters);
  if (std::any_of(cloud.points.begin(), cloud.points.end(), scene::isFar)) {
    return segmentScene(scene::withoutFarPoints(cloud), parameters);
  }
  SceneSegments result;
  const std::vector<int> finite = finiteIndices(cloud);
  if (finite.size() < static_cast<std::size_t>(parameters.min_cluster_points)) {
    result.note =
        "fewer finite points (" + std::to_string(finite.size()) + ") than min_cluster_points";
    return result;
  }
  result.organised = cloud.isOrganized() && cloud.width >= scene::kMinOrganisedSide &&
                     cloud.height >= scene::kMinOrganisedSide;
  const auto view = borrowed(cloud);
  if (parameters.max_support_planes > 0) {
    result.planes = result.organised ? scene::findOrganisedSupportPlanes(view, parameters)
                                     : scene::findRansacSupportPlanes(cloud, finite, parameters);
  }
  const std::vector<int> standing = scene::standingOn(cloud, finite, result.planes, parameters);
  std::vector<std::vector<int>> clusters =
      clustersOf(cloud, finite, standing, result.organised, parameters);
  capClusters(&clusters, parameters, &result);
  result.candidates = candidatesOf(cloud, clusters, standing, parameters);
  if (result.candidates.size() > static_cast<std::size_t>(parameters.max_candidates)) {
    const std::size_t excess =
        result.candidates.size() - static_cast<std::size_t>(parameters.max_candidates);
    result.candidates.resize(static_cast<std::size_t>(parameters.max_candidates));
    result.dropped_clusters += static_cast<int>(excess);
    result.note += std::to_string(excess) + " smallest split part(s) dropped (max_candidates " +
                   std::to_string(parameters.max_candidates) + "); ";
  }
  if (result.candidates.empty()) {
    result.note += std::string("no cluster of at least ") +
                   std::to_string(parameters.min_cluster_points) + " points" +
                   (result.planes.empty() ? " in the cloud (no support plane found)"
                                          : " stands on the support plane(s)");
  }
  return result;
}

SceneCandidate mergedCandidate(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                               const std::vector<const SceneCandidate*>& parts) {
  SceneCandidate merged;
  for (const SceneCandidate* part : parts) {
    merged.indices.insert(merged.indices.end(), part->indices.begin(), part->indices.end());
  }
  std::sort(merged.indices.begin(), merged.indices.end());
  merged.indices.erase(std::unique(merged.indices.begin(), merged.indices.end()),
                       merged.indices.end());
  if (merged.indices.empty()) return merged;
  scene::describeShape(cloud, &merged);
  merged.support = parts.front()->support;
  merged.cluster = parts.front()->cluster;
  merged.class_id = parts.front()->class_id;
  return merged;
}

}  // namespace vdc
