#include "view_direction_classification/ros/geometry_conversions.h"

#include <tf2_eigen/tf2_eigen.h>

#include <sstream>
#include <string>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/quaternion.h"

namespace vdc {

geometry_msgs::Quaternion toQuaternionMsg(const Eigen::Vector4d& wxyz) {
  geometry_msgs::Quaternion msg;
  msg.w = wxyz(0);
  msg.x = wxyz(1);
  msg.y = wxyz(2);
  msg.z = wxyz(3);
  return msg;
}

Eigen::Vector4d fromQuaternionMsg(const geometry_msgs::Quaternion& msg, const char* what) {
  const Eigen::Vector4d wxyz(msg.w, msg.x, msg.y, msg.z);
  checkUnitQuaternion(wxyz, what);
  return wxyz;
}

Eigen::Isometry3d toIsometry(const geometry_msgs::TransformStamped& transform) {
  const auto& t = transform.transform.translation;
  const auto& r = transform.transform.rotation;
  const Eigen::Vector3d translation(t.x, t.y, t.z);
  const Eigen::Vector4d rotation(r.w, r.x, r.y, r.z);
  if (!translation.allFinite() || !isUnitQuaternion(rotation)) {
    std::ostringstream message;
    message << "The transform from '" << transform.child_frame_id << "' to '"
            << transform.header.frame_id << "' is not a rigid motion (translation "
            << translation.transpose() << ", rotation (w,x,y,z) " << rotation.transpose() << ").";
    throw Error(message.str());
  }
  return tf2::transformToEigen(transform);
}

geometry_msgs::PoseWithCovariance toPoseWithCovarianceMsg(
    const Eigen::Vector3d& position, const Eigen::Vector4d& orientation_wxyz,
    const Eigen::Matrix3d& position_covariance, const Eigen::Matrix3d& orientation_covariance) {
  geometry_msgs::PoseWithCovariance msg;
  msg.pose.position = tf2::toMsg(position);
  msg.pose.orientation = toQuaternionMsg(orientation_wxyz);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      msg.covariance[i * 6 + j] = position_covariance(i, j);
      msg.covariance[(i + 3) * 6 + (j + 3)] = orientation_covariance(i, j);
    }
  }
  return msg;
}

}  // namespace vdc
