#include "view_direction_classification/geometry/camera.h"

#include <cmath>
#include <string>

#include "view_direction_classification/common/error.h"

namespace vdc {

void checkIntrinsics(const CameraIntrinsics& c) {
  if (c.width <= 0 || c.height <= 0) {
    throw Error("camera image size must be positive, got " + std::to_string(c.width) + "x" +
                std::to_string(c.height));
  }
  if (!(c.fx > 0.0) || !(c.fy > 0.0) || !std::isfinite(c.fx) || !std::isfinite(c.fy)) {
    throw Error("camera focal lengths must be positive and finite, got fx = " +
                std::to_string(c.fx) + ", fy = " + std::to_string(c.fy));
  }
  if (!std::isfinite(c.cx) || !std::isfinite(c.cy)) {
    throw Error("camera principal point must be finite");
  }
}

Eigen::Isometry3d cameraFromObject(const Eigen::Vector3d& view_direction, double distance,
                                   double roll) {
  const double length = view_direction.norm();
  if (!(length > 0.0) || !std::isfinite(length)) {
    throw Error("the viewing direction must be a non-zero finite vector");
  }
  if (!(distance > 0.0) || !std::isfinite(distance)) {
    throw Error("the camera distance must be positive and finite, got " + std::to_string(distance) +
                " m");
  }
  if (!std::isfinite(roll)) {
    throw Error("the camera roll must be finite");
  }
  const Eigen::Vector3d d = view_direction / length;
  // Camera axes expressed in the object frame: forward looks from the camera to the object.
  const Eigen::Vector3d forward = -d;
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ() - Eigen::Vector3d::UnitZ().dot(forward) * forward;
  if (up.norm() < 1e-6) {
    up = Eigen::Vector3d::UnitY() - Eigen::Vector3d::UnitY().dot(forward) * forward;
  }
  up.normalize();
  const Eigen::Vector3d down = -up;
  const Eigen::Vector3d right = down.cross(forward);  // x = y cross z (right-handed)
  Eigen::Matrix3d object_from_camera;
  object_from_camera << right, down, forward;
  object_from_camera = object_from_camera * Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitZ());

  Eigen::Isometry3d camera_from_object = Eigen::Isometry3d::Identity();
  camera_from_object.linear() = object_from_camera.transpose();
  // The camera centre sits at distance * d in the object frame and maps to the origin.
  camera_from_object.translation() = -camera_from_object.linear() * (distance * d);
  return camera_from_object;
}

Eigen::Vector3d viewDirectionOf(const Eigen::Isometry3d& camera_from_object) {
  const Eigen::Vector3d centre_in_object =
      -camera_from_object.linear().transpose() * camera_from_object.translation();
  const double length = centre_in_object.norm();
  if (!(length > 0.0) || !std::isfinite(length)) {
    throw Error(
        "the camera centre coincides with the object origin, so it has no viewing "
        "direction");
  }
  return centre_in_object / length;
}

}  // namespace vdc
