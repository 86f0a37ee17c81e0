#pragma once

#include <geometry_msgs/PoseWithCovariance.h>
#include <geometry_msgs/Quaternion.h>
#include <geometry_msgs/TransformStamped.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace vdc {

// The core keeps quaternions as Eigen::Vector4d in (w, x, y, z) order; ROS messages use
// (x, y, z, w). These convert between the two without normalising, so values pass unchanged.
geometry_msgs::Quaternion toQuaternionMsg(const Eigen::Vector4d& wxyz);
// Throws vdc::Error naming `what` (e.g. "axis 2 of component 5") for a non-finite or non-unit
// quaternion (tolerance 1e-6 on the norm), because every consumer of the core needs unit ones.
Eigen::Vector4d fromQuaternionMsg(const geometry_msgs::Quaternion& msg, const char* what);

// A tf transform (parent_from_child) as an isometry. Throws vdc::Error naming the transform's
// frames for a non-finite translation or a non-unit rotation (tf2 accepts such transforms from
// any broadcaster; the core must not see them).
Eigen::Isometry3d toIsometry(const geometry_msgs::TransformStamped& transform);

// A pose with its 6x6 covariance (row-major; x, y, z [m] then rotations about the fixed x, y, z
// axes [rad], as geometry_msgs/PoseWithCovariance defines it): `position_covariance` [m^2] in
// the position block, `orientation_covariance` [rad^2] in the rotation block, no cross terms.
geometry_msgs::PoseWithCovariance toPoseWithCovarianceMsg(
    const Eigen::Vector3d& position, const Eigen::Vector4d& orientation_wxyz,
    const Eigen::Matrix3d& position_covariance, const Eigen::Matrix3d& orientation_covariance);

}  // namespace vdc
