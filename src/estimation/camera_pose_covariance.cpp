#include "view_direction_classification/estimation/camera_pose_covariance.h"

#include <cmath>
#include <string>

#include "view_direction_classification/common/error.h"

namespace vdc {

Eigen::Matrix3d cameraPosePositionCovariance(const Eigen::Vector3d& camera_to_object,
                                             double rotation_deg, double shift_mm) {
  if (!(rotation_deg >= 0.0) || !std::isfinite(rotation_deg) || !(shift_mm >= 0.0) ||
      !std::isfinite(shift_mm)) {
    throw Error("the camera pose uncertainty must be finite and >= 0, got " +
                std::to_string(rotation_deg) + " deg and " + std::to_string(shift_mm) + " mm");
  }
  const double rotation_per_axis = rotation_deg * M_PI / 180.0 / std::sqrt(3.0);
  const double shift_per_axis = shift_mm / 1000.0 / std::sqrt(3.0);
  const Eigen::Matrix3d across_line_of_sight =
      camera_to_object.squaredNorm() * Eigen::Matrix3d::Identity() -
      camera_to_object * camera_to_object.transpose();
  return rotation_per_axis * rotation_per_axis * across_line_of_sight +
         shift_per_axis * shift_per_axis * Eigen::Matrix3d::Identity();
}

}  // namespace vdc
