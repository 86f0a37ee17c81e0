#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <optional>

namespace vdc {

// Where the estimator last saw the object, in the fixed frame (the object is static there; the
// camera moves). Between featurised frames it is followed at the cost of one pass over each
// cloud (doc/method.md section 12).
struct ObjectTrack {
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  // of the object points last seen
  // The table under it (n . x + d = 0, unit n upwards, towards the cameras); empty: none known.
  std::optional<Eigen::Vector4d> table;
};

enum class SightingStatus {
  kSeen,       // object points where the track expects them
  kLeft,       // the place is in view and empty: the camera sees the table or more behind it
  kNotInView,  // too few points there and nothing seen through it (out of the view, occluded)
};

struct ObjectSighting {
  SightingStatus status = SightingStatus::kNotInView;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();  // fixed frame, when seen
  int points = 0;                                      // object points found around the track
  int seen_through = 0;                                // points seen behind the tracked place
};

struct SightingParameters {
  // [m] The object's points lie within this distance of the centroid of any of its views; 0:
  // every finite point is the object's (segmentation none).
  double radius = 0.0;
  // [m] Rays passing this close to the tracked centroid that end this much beyond it show the
  // place empty.
  double see_through_distance = 0.02;
  double table_distance = 0.008;  // [m] points this close to the table (or below it) are table
  int min_points = 50;            // fewer object points: not seen
};

// One pass over `cloud` (camera frame, NaN allowed) with the camera at world_from_camera: the
// object points around the track (not on or under its table), their centroid and the rays seen
// through the tracked place.
ObjectSighting lookForTrackedObject(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                    const Eigen::Isometry3d& world_from_camera,
                                    const ObjectTrack& track, const SightingParameters& parameters);

}  // namespace vdc
