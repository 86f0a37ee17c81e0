#include "view_direction_classification/estimation/object_tracking.h"

#include <cmath>

#include "view_direction_classification/geometry/measured_point.h"

namespace vdc {

ObjectSighting lookForTrackedObject(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                    const Eigen::Isometry3d& world_from_camera,
                                    const ObjectTrack& track,
                                    const SightingParameters& parameters) {
  const Eigen::Isometry3d camera_from_world = world_from_camera.inverse();
  const Eigen::Vector3d centre = camera_from_world * track.centroid;
  std::optional<Eigen::Vector4d> table;  // in the camera frame
  if (track.table) {
    const Eigen::Vector3d normal = camera_from_world.linear() * track.table->head<3>();
    const double offset = (*track.table)(3) - normal.dot(camera_from_world.translation());
    table = Eigen::Vector4d(normal.x(), normal.y(), normal.z(), offset);
  }
  const double radius2 = parameters.radius * parameters.radius;
  const double near2 = parameters.see_through_distance * parameters.see_through_distance;
  ObjectSighting sighting;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const pcl::PointXYZ& point : cloud.points) {
    if (!isMeasuredPoint(point)) continue;
    const Eigen::Vector3d p = point.getVector3fMap().cast<double>();
    if (table && table->head<3>().dot(p) + (*table)(3) <= parameters.table_distance) {
      // The table itself; behind the tracked place it still shows that place empty.
    } else if (parameters.radius <= 0.0 || (p - centre).squaredNorm() <= radius2) {
      sum += p;
      ++sighting.points;
      continue;
    }
    if (parameters.radius <= 0.0) continue;
    // The ray from the camera through p passes the tracked centroid at distance |c x p| / |p|
    // and ends |p| - c . p / |p| beyond its closest approach.
    const double length = p.norm();
    if (length <= 0.0) continue;
    const Eigen::Vector3d ray = p / length;
    const double along = ray.dot(centre);
    if (along > 0.0 && (centre - along * ray).squaredNorm() <= near2 &&
        length - along > parameters.see_through_distance) {
      ++sighting.seen_through;
    }
  }
  if (sighting.points >= parameters.min_points) {
    sighting.status = SightingStatus::kSeen;
    sighting.centroid = world_from_camera * (sum / sighting.points);
  } else if (sighting.seen_through >= parameters.min_points) {
    sighting.status = SightingStatus::kLeft;
  }
  return sighting;
}

}  // namespace vdc
