#include "view_direction_classification/estimation/tabletop_segmentation.h"

#include <pcl/ModelCoefficients.h>
#include <pcl/PointIndices.h>
#include <pcl/search/kdtree.h>
#include <pcl/segmentation/extract_clusters.h>
#include <pcl/segmentation/sac_segmentation.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>
#include <unordered_map>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

// RANSAC on more points finds the same table, only slower.
constexpr std::size_t kMaxPlanePoints = 20000;
// A plane counts as a table only if its inliers spread wider than this many model diagonals:
// smaller planes are faces of the object itself (the mug's bottom seen from below).
constexpr double kMinTableWidthInDiagonals = 1.5;
// What stands on the table is kept up to this many model diagonals above it (walls and people
// behind the table are not candidates).
constexpr double kMaxHeightInDiagonals = 1.5;

double signedDistance(const Eigen::Vector4d& plane, const pcl::PointXYZ& p) {
  return plane.head<3>().dot(p.getVector3fMap().cast<double>()) + plane(3);
}

// Diagonal [m] of the bounding box of the points within `distance` of the plane.
double planeWidth(const pcl::PointCloud<pcl::PointXYZ>& points, const Eigen::Vector4d& plane,
                  double distance) {
  Eigen::AlignedBox3d box;
  for (const pcl::PointXYZ& p : points.points) {
    if (std::abs(signedDistance(plane, p)) <= distance)
      box.extend(p.getVector3fMap().cast<double>());
  }
  return box.isEmpty() ? 0.0 : box.diagonal().norm();
}

// Centroid and the largest extent along the principal axes of the points at `indices`.
void describeCluster(const pcl::PointCloud<pcl::PointXYZ>& points, TabletopCluster* cluster) {
  const double n = static_cast<double>(cluster->indices.size());
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const int i : cluster->indices) mean += points[i].getVector3fMap().cast<double>();
  mean /= n;
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const int i : cluster->indices) {
    const Eigen::Vector3d d = points[i].getVector3fMap().cast<double>() - mean;
    scatter += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(scatter / n);
  const Eigen::Matrix3d axes = solver.eigenvectors();
  Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d high = -low;
  for (const int i : cluster->indices) {
    const Eigen::Vector3d projected =
        axes.transpose() * (points[i].getVector3fMap().cast<double>() - mean);
    low = low.cwiseMin(projected);
    high = high.cwiseMax(projected);
  }
  cluster->centroid = mean;
  cluster->largest_extent = (high - low).maxCoeff();
}

// One point per voxel of this fraction of the clustering tolerance is clustered, the others
// join their voxel's cluster: at 0.6 m a depth camera's points are ~1 mm apart, so a 1 cm radius
// search on all of them returns hundreds of neighbours per point (seconds per scene), on the
// voxel representatives tens.
constexpr double kVoxelFractionOfTolerance = 0.3;

std::vector<TabletopCluster> clustersOf(const pcl::PointCloud<pcl::PointXYZ>& points,
                                        const std::vector<int>& candidates,
                                        const TabletopParameters& parameters) {
  std::vector<TabletopCluster> clusters;
  if (candidates.size() < static_cast<std::size_t>(parameters.min_cluster_points)) return clusters;
  const double voxel = kVoxelFractionOfTolerance * parameters.cluster_tolerance;
  std::unordered_map<std::uint64_t, int> voxel_of_key;  // -> index into representatives
  std::vector<int> voxel_of_candidate(candidates.size());
  pcl::PointCloud<pcl::PointXYZ>::Ptr representatives(new pcl::PointCloud<pcl::PointXYZ>);
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    const Eigen::Vector3f& p = points[candidates[k]].getVector3fMap();
    // 21 bits per axis: 2^21 voxels of a few mm cover kilometres.
    std::uint64_t key = 0;
    for (int axis = 0; axis < 3; ++axis) {
      const auto cell = static_cast<std::int64_t>(std::floor(p(axis) / voxel));
      key = (key << 21) | (static_cast<std::uint64_t>(cell) & ((1u << 21) - 1));
    }
    const auto [entry, inserted] =
        voxel_of_key.emplace(key, static_cast<int>(representatives->size()));
    if (inserted) representatives->push_back(points[candidates[k]]);
    voxel_of_candidate[k] = entry->second;
  }
  pcl::search::KdTree<pcl::PointXYZ>::Ptr tree(new pcl::search::KdTree<pcl::PointXYZ>);
  tree->setInputCloud(representatives);
  pcl::EuclideanClusterExtraction<pcl::PointXYZ> clustering;
  clustering.setClusterTolerance(parameters.cluster_tolerance);
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
  std::vector<TabletopCluster> all(found.size());
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    const int c = cluster_of_voxel[static_cast<std::size_t>(voxel_of_candidate[k])];
    if (c >= 0) all[static_cast<std::size_t>(c)].indices.push_back(candidates[k]);
  }
  for (TabletopCluster& cluster : all) {
    if (cluster.indices.size() < static_cast<std::size_t>(parameters.min_cluster_points)) continue;
    describeCluster(points, &cluster);
    clusters.push_back(std::move(cluster));
  }
  std::stable_sort(clusters.begin(), clusters.end(),
                   [](const TabletopCluster& a, const TabletopCluster& b) {
                     return a.indices.size() > b.indices.size();
                   });
  return clusters;
}

std::string noFitReason(const std::vector<TabletopCluster>& clusters, double low, double high) {
  std::string sizes;
  char text[64];
  for (std::size_t c = 0; c < clusters.size() && c < 5; ++c) {
    std::snprintf(text, sizeof(text), "%s%.3f", c ? ", " : "", clusters[c].largest_extent);
    sizes += text;
  }
  if (clusters.size() > 5) sizes += ", ...";
  std::snprintf(text, sizeof(text), "%.3f to %.3f m", low, high);
  return "no cluster on the table fits the model's size (largest extents " + sizes +
         " m; the model's views span " + text + ")";
}

}  // namespace

ObjectExtent ObjectExtent::of(const Eigen::AlignedBox3d& bounds) {
  if (bounds.isEmpty() || !bounds.min().allFinite() || !bounds.max().allFinite()) {
    throw Error("the object's bounding box is empty or not finite");
  }
  ObjectExtent extent;
  extent.sizes = bounds.sizes();
  std::sort(extent.sizes.data(), extent.sizes.data() + 3, std::greater<double>());
  return extent;
}

std::optional<Eigen::Vector4d> findDominantPlane(const pcl::PointCloud<pcl::PointXYZ>& points,
                                                 double distance, double min_fraction) {
  if (points.size() < 3) return std::nullopt;
  pcl::PointCloud<pcl::PointXYZ>::Ptr sample(new pcl::PointCloud<pcl::PointXYZ>);
  const std::size_t stride = (points.size() + kMaxPlanePoints - 1) / kMaxPlanePoints;
  for (std::size_t i = 0; i < points.size(); i += stride) sample->push_back(points[i]);
  pcl::SACSegmentation<pcl::PointXYZ> ransac;  // deterministic: PCL seeds its RNG with a constant
  ransac.setModelType(pcl::SACMODEL_PLANE);
  ransac.setMethodType(pcl::SAC_RANSAC);
  ransac.setDistanceThreshold(distance);
  ransac.setMaxIterations(200);
  ransac.setOptimizeCoefficients(true);
  ransac.setInputCloud(sample);
  pcl::PointIndices inliers;
  pcl::ModelCoefficients coefficients;
  ransac.segment(inliers, coefficients);
  if (coefficients.values.size() != 4 || static_cast<double>(inliers.indices.size()) <
                                             min_fraction * static_cast<double>(sample->size())) {
    return std::nullopt;
  }
  Eigen::Vector4d plane(coefficients.values[0], coefficients.values[1], coefficients.values[2],
                        coefficients.values[3]);
  const double length = plane.head<3>().norm();
  if (!(length > 0.0) || !plane.allFinite()) return std::nullopt;
  plane /= length;
  if (plane(3) < 0) plane = -plane;  // the camera (origin) on the positive side
  return plane;
}

TabletopResult segmentTabletop(const pcl::PointCloud<pcl::PointXYZ>& points,
                               const TabletopParameters& parameters, const ObjectExtent& extent,
                               const std::optional<Eigen::Vector3d>& expected_centroid) {
  TabletopResult result;
  const double diagonal = extent.diagonal();
  result.table =
      findDominantPlane(points, parameters.plane_distance, parameters.min_plane_fraction);
  if (result.table && planeWidth(points, *result.table, parameters.plane_distance) <
                          kMinTableWidthInDiagonals * diagonal) {
    result.table.reset();
  }
  std::vector<int> candidates;
  candidates.reserve(points.size());
  for (int i = 0; i < static_cast<int>(points.size()); ++i) {
    if (result.table) {
      const double height = signedDistance(*result.table, points[i]);
      if (height <= parameters.plane_distance || height > kMaxHeightInDiagonals * diagonal)
        continue;
    }
    candidates.push_back(i);
  }
  result.clusters = clustersOf(points, candidates, parameters);
  if (result.clusters.empty()) {
    result.failure =
        std::string(result.table ? "nothing stands on the table" : "no table found and") +
        " (no cluster of at least " + std::to_string(parameters.min_cluster_points) + " points" +
        (result.table ? " above it)" : " in the cloud)");
    return result;
  }
  const double low = (1.0 - parameters.extent_tolerance) * extent.sizes.minCoeff();
  const double high = (1.0 + parameters.extent_tolerance) * diagonal;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t c = 0; c < result.clusters.size(); ++c) {
    TabletopCluster& cluster = result.clusters[c];
    cluster.fits = cluster.largest_extent >= low && cluster.largest_extent <= high;
    if (!cluster.fits) continue;
    // Nearest to where the object was; without that, the biggest (clusters come largest first).
    const double score =
        expected_centroid ? (cluster.centroid - *expected_centroid).norm() : static_cast<double>(c);
    if (score < best) {
      best = score;
      result.chosen = static_cast<int>(c);
    }
  }
  if (result.chosen < 0) result.failure = noFitReason(result.clusters, low, high);
  return result;
}

}  // namespace vdc
