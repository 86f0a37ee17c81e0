#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <vector>

namespace vdc {

// How a whole scene's depth cloud is cut into object candidates (segmentScene).
struct SceneSegmentationParameters {
  // A structured-light camera's depth noise and disparity steps grow with the square of the
  // depth z (Kinect: sigma 1.9 mm and steps 2.9 mm at 1 m, 6.1 mm and 1.1 cm at 2 m), and a real
  // table departs from a plane more where it is far. So plane_distance and cluster_tolerance are
  // the tolerances near the camera; at depth z [m] each is larger by depth_tolerance_growth * z^2.
  // 0.003 is a Kinect-class camera's disparity step at 1 m; 0 keeps the tolerances fixed.
  double depth_tolerance_growth = 0.003;  // [m per m^2]

  // Support planes (tables, shelves).
  // [m] plane inliers near the camera (grows with depth); what stands on a plane starts this far
  // above it.
  double plane_distance = 0.008;
  int min_plane_points = 2000;  // inliers a plane needs to be a support
  // [m] a support is at least this wide across (its inliers' second principal extent): narrower
  // planes are faces of the objects themselves (a box's top).
  double min_plane_width = 0.25;
  // Organised clouds: neighbouring normals within this angle [deg] grow one plane region.
  double plane_angle_deg = 3.0;
  // Supports besides the largest plane are parallel to it within this angle [deg] (shelves, a
  // raised board); other planes (walls) are no supports.
  double max_support_tilt_deg = 15.0;
  int max_support_planes = 3;
  double max_height_above_plane = 0.5;  // [m] what stands higher is background (walls, people)

  // Object clusters.
  // [m] neighbours closer than this near the camera (grows with depth) are one cluster
  double cluster_tolerance = 0.01;
  int min_cluster_points = 50;      // smaller clusters (and split parts) are noise, not counted
  int max_cluster_points = 200000;  // larger clusters are dropped (a wall, not an object)
  int max_candidates = 30;          // the largest are kept, the rest counted as dropped

  // Touching objects: clusters are split at concave edges (supervoxels + LCCP).
  bool split_touching = true;
  double supervoxel_voxel = 0.004;  // [m] voxel of the supervoxel adjacency octree
  // [m] spacing of the supervoxel seeds: small enough that no supervoxel straddles the contact of
  // a can and a box (2.5 cm ones do and join them).
  double supervoxel_seed = 0.02;
  // Edges more concave than this [deg] separate parts; 10 (LCCP's usual) keeps a can and a box
  // together where they touch.
  double concavity_tolerance_deg = 5.0;
  // A convex part with fewer than this fraction of its cluster's points stays with the part it
  // touches (a mug's handle is concave to its body but no object of its own).
  double min_part_fraction = 0.15;

  // A detector's label image instead (segmentLabels, label_segmentation.h): a label value's class
  // is value / label_class_divisor. 1000 is the Cityscapes instance images' convention (26001:
  // instance 1 of class 26); 1 makes the value itself the class.
  int label_class_divisor = 1000;
};

// Throws vdc::Error naming the first parameter that is out of range or not finite.
void checkSceneSegmentationParameters(const SceneSegmentationParameters& parameters);

// A supporting plane: coefficients.head<3>() . x + coefficients(3) = 0 with unit normal pointing
// towards the camera (the origin of the cloud's frame, so coefficients(3) > 0).
struct SupportPlane {
  Eigen::Vector4d coefficients = Eigen::Vector4d::Zero();
  int inliers = 0;  // points of the cloud within plane_distance (at their depth) of it
};

// One object candidate: the points of one object (or of several that could not be told apart).
struct SceneCandidate {
  std::vector<int> indices;  // into the segmented cloud, ascending
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  // Sides [m] of its box along its principal axes, largest first; axes.col(k) is side k's axis.
  Eigen::Vector3d extent = Eigen::Vector3d::Zero();
  Eigen::Matrix3d axes = Eigen::Matrix3d::Identity();
  int support = -1;  // index into SceneSegments::planes it stands on, -1: none found
  // The detector's class of its label (segmentLabels), -1: geometric segmentation, no class.
  std::int64_t class_id = -1;
  // The connected cluster it was split from (split_touching): candidates of one cluster touch.
  // Numbered per segmentation; -1 where there are no clusters (label masks).
  int cluster = -1;
  int pointCount() const { return static_cast<int>(indices.size()); }
};

struct SceneSegments {
  std::vector<SupportPlane> planes;        // largest first
  std::vector<SceneCandidate> candidates;  // most points first
  int dropped_clusters = 0;                // clusters over the caps (see note)
  std::string note;                        // why clusters were dropped, or why none was found
  bool organised = false;                  // which path segmented the cloud
};

// Cuts a scene into the object candidates standing on its support planes. Organised clouds
// (width x height, NaN where there is no depth) use image neighbourhoods: integral-image
// normals, organised multi-plane segmentation, connected components. Unorganised clouds use
// RANSAC planes and Euclidean clustering. Without a support plane everything is clustered.
// Touching objects are split at concave edges if parameters.split_touching. Deterministic; never
// throws for the cloud's content (empty, all NaN, huge); throws vdc::Error for invalid parameters.
SceneSegments segmentScene(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                           const SceneSegmentationParameters& parameters);

// The candidate that `parts` (candidates of `cloud`, at least one) make together: their indices
// merged, described as segmentScene describes one, standing on the first part's support, of the
// first part's cluster, with its class.
SceneCandidate mergedCandidate(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                               const std::vector<const SceneCandidate*>& parts);

}  // namespace vdc
