#include "object_clusters.h"

#include <pcl/PointIndices.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/comparator.h>
#include <pcl/segmentation/organized_connected_component_segmentation.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <unordered_map>

#include "support_planes.h"

namespace vdc::scene {
namespace {

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

// Whether two points are one cluster's neighbours: closer than the tolerance at the nearer one's
// depth. Symmetric, so the clusters do not depend on the order the points are visited in.
bool neighbours(const pcl::PointXYZ& a, const pcl::PointXYZ& b, const DepthTolerance& tolerance) {
  const pcl::PointXYZ& nearer = std::abs(a.z) < std::abs(b.z) ? a : b;
  const double limit = toleranceAt(tolerance, nearer);
  return (a.getVector3fMap() - b.getVector3fMap()).cast<double>().squaredNorm() < limit * limit;
}

// Image neighbours of the standing points closer than the depth's tolerance. PCL's
// EuclideanClusterComparator scales its threshold by z^2 alone, which near the camera falls below
// the sensor's fixed noise; this one adds the fixed part.
class StandingComparator : public pcl::Comparator<pcl::PointXYZ> {
 public:
  StandingComparator(const std::vector<int>& standing, DepthTolerance tolerance)
      : standing_(standing), tolerance_(tolerance) {}

  bool compare(int a, int b) const override {
    if (standing_[static_cast<std::size_t>(a)] == kNotStanding ||
        standing_[static_cast<std::size_t>(b)] == kNotStanding) {
      return false;
    }
    return neighbours((*input_)[a], (*input_)[b], tolerance_);
  }

 private:
  const std::vector<int>& standing_;
  DepthTolerance tolerance_;
};

// The connected components of the voxel representatives (neighbours() as edges), a component
// index per representative. A radius search at the representative's depth finds every neighbour:
// the nearer of two has the smaller tolerance.
std::vector<int> representativeComponents(const pcl::PointCloud<pcl::PointXYZ>::Ptr& points,
                                          const DepthTolerance& tolerance) {
  pcl::search::KdTree<pcl::PointXYZ> tree;
  tree.setInputCloud(points);
  std::vector<int> component(points->size(), -1);
  std::vector<int> found, frontier;
  std::vector<float> distances;
  int components = 0;
  for (std::size_t seed = 0; seed < points->size(); ++seed) {
    if (component[seed] >= 0) continue;
    component[seed] = components;
    frontier.assign(1, static_cast<int>(seed));
    while (!frontier.empty()) {
      const pcl::PointXYZ& p = (*points)[frontier.back()];
      frontier.pop_back();
      tree.radiusSearch(p, toleranceAt(tolerance, p), found, distances);
      for (const int k : found) {
        if (component[static_cast<std::size_t>(k)] >= 0 || !neighbours(p, (*points)[k], tolerance))
          continue;
        component[static_cast<std::size_t>(k)] = components;
        frontier.push_back(k);
      }
    }
    ++components;
  }
  return component;
}

std::vector<std::vector<int>> largeEnough(std::vector<std::vector<int>> all, int min_points) {
  std::vector<std::vector<int>> clusters;
  for (std::vector<int>& cluster : all) {
    if (cluster.size() >= static_cast<std::size_t>(min_points))
      clusters.push_back(std::move(cluster));
  }
  return clusters;
}

}  // namespace

std::vector<std::vector<int>> organisedClusters(
    const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& cloud, const std::vector<int>& standing,
    const DepthTolerance& tolerance, int min_points) {
  const auto comparator = std::make_shared<StandingComparator>(standing, tolerance);
  comparator->setInputCloud(cloud);
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
                                                const std::vector<int>& indices,
                                                const DepthTolerance& tolerance, int min_points) {
  // The voxel is a fraction of the smallest tolerance (near the camera), so it holds anywhere.
  const double voxel = kVoxelFractionOfTolerance * tolerance.near;
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
  const std::vector<int> component = representativeComponents(representatives, tolerance);
  const int components = *std::max_element(component.begin(), component.end()) + 1;
  std::vector<std::vector<int>> all(static_cast<std::size_t>(components));
  for (std::size_t k = 0; k < indices.size(); ++k) {
    const int c = component[static_cast<std::size_t>(voxel_of_point[k])];
    all[static_cast<std::size_t>(c)].push_back(indices[k]);
  }
  return largeEnough(std::move(all), min_points);
}

}  // namespace vdc::scene
