#include "view_direction_classification/ros/geometry_conversions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/quaternion.h"

namespace vdc {
namespace {

TEST(GeometryConversions, QuaternionGoesToRosOrderAndBackBitForBit) {
  const Eigen::Vector4d wxyz = Eigen::Vector4d(0.3, -0.5, 0.1, 0.7).normalized();
  const geometry_msgs::Quaternion msg = toQuaternionMsg(wxyz);
  EXPECT_EQ(msg.w, wxyz(0));
  EXPECT_EQ(msg.x, wxyz(1));
  EXPECT_EQ(msg.y, wxyz(2));
  EXPECT_EQ(msg.z, wxyz(3));
  EXPECT_EQ(fromQuaternionMsg(msg, "q"), wxyz);
}

TEST(GeometryConversions, RefusesNonUnitQuaternionNamingIt) {
  geometry_msgs::Quaternion msg;  // all zero
  try {
    fromQuaternionMsg(msg, "the test quaternion");
    FAIL() << "accepted a zero quaternion";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("the test quaternion"), std::string::npos);
  }
}

TEST(GeometryConversions, TransformBecomesTheSameRigidMotion) {
  geometry_msgs::TransformStamped transform;
  transform.header.frame_id = "world";
  transform.child_frame_id = "camera";
  const Eigen::Vector4d q = quaternionFromAxisAngle(Eigen::Vector3d(1, 2, 3), 0.7);
  transform.transform.rotation = toQuaternionMsg(q);
  transform.transform.translation.x = 0.5;
  transform.transform.translation.y = -1.0;
  transform.transform.translation.z = 2.0;
  const Eigen::Isometry3d pose = toIsometry(transform);
  const Eigen::Vector3d p(0.1, 0.2, 0.3);
  const Eigen::Vector3d expected = rotateVector(q, p) + Eigen::Vector3d(0.5, -1.0, 2.0);
  EXPECT_LT((pose * p - expected).norm(), 1e-12);
}

TEST(GeometryConversions, RefusesNaNTransformNamingItsFrames) {
  geometry_msgs::TransformStamped transform;
  transform.header.frame_id = "world";
  transform.child_frame_id = "camera";
  transform.transform.rotation.w = 1.0;
  transform.transform.translation.y = std::numeric_limits<double>::quiet_NaN();
  try {
    toIsometry(transform);
    FAIL() << "accepted a NaN translation";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("from 'camera' to 'world'"), std::string::npos)
        << error.what();
  }
}

}  // namespace
}  // namespace vdc

namespace vdc {
namespace {

TEST(GeometryConversions, PoseCovarianceHasPositionAndOrientationBlocksOnly) {
  Eigen::Matrix3d orientation, position;
  orientation << 0.04, 0.01, 0.0, 0.01, 0.09, 0.02, 0.0, 0.02, 0.16;
  position << 4e-6, 1e-6, 0.0, 1e-6, 9e-6, -2e-6, 0.0, -2e-6, 2.5e-5;
  const geometry_msgs::PoseWithCovariance msg = toPoseWithCovarianceMsg(
      Eigen::Vector3d(1, 2, 3), Eigen::Vector4d(1, 0, 0, 0), position, orientation);
  EXPECT_EQ(msg.pose.position.y, 2.0);
  EXPECT_EQ(msg.pose.orientation.w, 1.0);
  for (int i = 0; i < 6; ++i) {
    for (int j = 0; j < 6; ++j) {
      double expected = 0.0;
      if (i < 3 && j < 3) expected = position(i, j);
      if (i >= 3 && j >= 3) expected = orientation(i - 3, j - 3);
      EXPECT_EQ(msg.covariance[i * 6 + j], expected) << "row " << i << " column " << j;
    }
  }
}

}  // namespace
}  // namespace vdc
