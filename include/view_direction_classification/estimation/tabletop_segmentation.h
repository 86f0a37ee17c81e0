#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <optional>
#include <string>
#include <vector>

namespace vdc {

// The object's size as its model knows it: the sides of its bounding box, largest first.
struct ObjectExtent {
  Eigen::Vector3d sizes = Eigen::Vector3d::Zero();
  double diagonal() const { return sizes.norm(); }
  // From a model bundle's bounds; throws vdc::Error for an empty or non-finite box.
  static ObjectExtent of(const Eigen::AlignedBox3d& bounds);
};

// The dominant plane of `points` (RANSAC with inlier distance `distance`, on at most 20000
// evenly strided points) if it holds at least `min_fraction` of them: n . x + d = 0 with unit n
// pointing towards the origin of the points' frame (the camera). Deterministic.
std::optional<Eigen::Vector4d> findDominantPlane(const pcl::PointCloud<pcl::PointXYZ>& points,
                                                 double distance, double min_fraction);

struct TabletopParameters {
  double plane_distance = 0.008;     // [m] table inliers; the object starts this far above
  double min_plane_fraction = 0.15;  // of the points, for a plane to count as a table
  double cluster_tolerance = 0.01;   // [m]
  int min_cluster_points = 50;
  double extent_tolerance = 0.15;
};

// One cluster of points standing on the table.
struct TabletopCluster {
  std::vector<int> indices;  // into the searched points
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  double largest_extent = 0.0;  // [m] along its first principal axis
  bool fits = false;            // its size fits the model's extent
};

struct TabletopResult {
  std::optional<Eigen::Vector4d> table;  // as findDominantPlane; empty: no table, all clustered
  std::vector<TabletopCluster> clusters;
  int chosen = -1;      // index into clusters, -1 when none fits
  std::string failure;  // why none was chosen
};

// Tabletop segmentation of finite `points`: removes the table (a dominant plane wider than the
// object; none found: everything is clustered), keeps what stands on it up to 1.5 model
// diagonals high, clusters it (Euclidean, one point per voxel of 0.3 tolerances) and chooses the
// fitting cluster nearest to `expected_centroid` if given, else the fitting cluster with the most
// points.
TabletopResult segmentTabletop(const pcl::PointCloud<pcl::PointXYZ>& points,
                               const TabletopParameters& parameters, const ObjectExtent& extent,
                               const std::optional<Eigen::Vector3d>& expected_centroid);

}  // namespace vdc
