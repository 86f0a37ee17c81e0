#include "object_clusters.h"

#include <pcl/PointIndices.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/euclidean_cluster_comparator.h>
#include <pcl/segmentation/extract_clusters.h>
#include <pcl/segmentation/organized_connected_component_segmentation.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <set>
#include <unordered_map>

#include "support_planes.h"

namespace vdc::scene {
namespace {

// Label of the points that may join a cluster (the others are 0).
constexpr std::uint32_t kStandingLabel = 1;

// One point per voxel of this fraction of the clustering tolerance is clustered, the others join
// their voxel's cluster: at 0.6 m a depth camera's points are ~1 mm apart, so a 1 cm radius
// search on all of them returns hundreds of neighbours per point, on the voxel representatives
// tens. Two points in one voxel are closer than the tolerance, so the clusters are the same.
constexpr double kVoxelFractionOfTolerance = 0.3;

std::uint64_t voxelKey(const pcl::PointXYZ& p, double voxel) {
  // 21 bits per axis: 2^21 voxels of a few mm cover kilometres.
  std::uint64_t key = 0;
  for (int axis = 0; axis < 3; ++axis) {
    const auto cell = static_cast<std::int64_t>(std::floor(p.data[axis] / voxel));
    key = (key << 21) | (static_cast<std::uint64_t>(cell) & ((1u << 21) - 1));
  }
  return key;
}

}  // namespace

std::vector<std::vector<int>> organisedClusters(
    const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud, const std::vector<int>& standing,
    double tolerance, int min_points) {
  pcl::PointCloud<pcl::Label>::Ptr labels(new pcl::PointCloud<pcl::Label>);
  labels->resize(cloud->size());
  for (std::size_t i = 0; i < cloud->size(); ++i)
    (*labels)[i].label = standing[i] == kNotStanding ? 0 : kStandingLabel;
  // PCL 1.13's comparator joins two points only if both labels are IN this "exclude" set (its
  // compare() returns false for labels missing from it), so the set names the labels to keep.
  const auto joinable = std::make_shared<std::set<std::uint32_t>>();
  joinable->insert(kStandingLabel);
  const auto comparator =
      std::make_shared<pcl::EuclideanClusterComparator<pcl::PointXYZ, pcl::Label>>();
  comparator->setInputCloud(cloud);
  comparator->setLabels(labels);
  comparator->setExcludeLabels(joinable);
  // Not depth dependent: the same tolerance as the unorganised path, so both find the same.
  comparator->setDistanceThreshold(static_cast<float>(tolerance), false);

  pcl::OrganizedConnectedComponentSegmentation<pcl::PointXYZ, pcl::Label> components(comparator);
  components.setInputCloud(cloud);
  pcl::PointCloud<pcl::Label> component_labels;
  std::vector<pcl::PointIndices> component_indices;
  components.segment(component_labels, component_indices);

  std::vector<std::vector<int>> clusters;
  for (pcl::PointIndices& component : component_indices) {
    if (component.indices.size() < static_cast<std::size_t>(min_points)) continue;
    // A component of points that may not be clustered (a plane) is no object.
    if (standing[static_cast<std::size_t>(component.indices.front())] == kNotStanding) continue;
    clusters.push_back(std::move(component.indices));
  }
  return clusters;
}

std::vector<std::vector<int>> euclideanClusters(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                                const std::vector<int>& indices, double tolerance,
                                                int min_points) {
  const double voxel = kVoxelFractionOfTolerance * tolerance;
  std::unordered_map<std::uint64_t, int> voxel_of_key;  // -> index into representatives
  std::vector<int> voxel_of_point(indices.size());
  pcl::PointCloud<pcl::PointXYZ>::Ptr representatives(new pcl::PointCloud<pcl::PointXYZ>);
  for (std::size_t k = 0; k < indices.size(); ++k) {
    const pcl::PointXYZ& p = cloud[indices[k]];
    const auto [entry, inserted] =
        voxel_of_key.emplace(voxelKey(p, voxel), static_cast<int>(representatives->size()));
    if (inserted) representatives->push_back(p);
    voxel_of_point[k] = entry->second;
  }
  if (representatives->empty()) return {};
  pcl::search::KdTree<pcl::PointXYZ>::Ptr tree(new pcl::search::KdTree<pcl::PointXYZ>);
  tree->setInputCloud(representatives);
  pcl::EuclideanClusterExtraction<pcl::PointXYZ> clustering;
  clustering.setClusterTolerance(tolerance);
  clustering.setMinClusterSize(1);  // the point count is judged at full resolution below
  clustering.setMaxClusterSize(std::numeric_limits<int>::max());
  clustering.setSearchMethod(tree);
  clustering.setInputCloud(representatives);
  std::vector<pcl::PointIndices> found;
  clustering.extract(found);

  std::vector<int> cluster_of_voxel(representatives->size(), -1);
  for (std::size_t c = 0; c < found.size(); ++c) {
    for (const int v : found[c].indices)
      cluster_of_voxel[static_cast<std::size_t>(v)] = static_cast<int>(c);
  }
  std::vector<std::vector<int>> all(found.size());
  for (std::size_t k = 0; k < indices.size(); ++k) {
    const int c = cluster_of_voxel[static_cast<std::size_t>(voxel_of_point[k])];
    if (c >= 0) all[static_cast<std::size_t>(c)].push_back(indices[k]);
  }
  std::vector<std::vector<int>> clusters;
  for (std::vector<int>& cluster : all) {
    if (cluster.size() >= static_cast<std::size_t>(min_points))
      clusters.push_back(std::move(cluster));
  }
  return clusters;
}

}  // namespace vdc::scene
