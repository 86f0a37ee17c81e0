#include "view_direction_classification/estimation/camera_pose_covariance.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <limits>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

constexpr double kDegree = M_PI / 180.0;

TEST(CameraPosePositionCovariance, ARotationErrorMovesTheObjectAcrossTheLineOfSightOnly) {
  // The object 0.6 m along the camera's x axis (fixed frame), an RMS rotation error of 2 degrees.
  const Eigen::Matrix3d covariance =
      cameraPosePositionCovariance(Eigen::Vector3d(0.6, 0.0, 0.0), 2.0, 0.0);
  const double across = std::pow(0.6 * 2.0 * kDegree / std::sqrt(3.0), 2);
  EXPECT_NEAR(covariance(0, 0), 0.0, 1e-15) << "nothing along the line of sight";
  EXPECT_NEAR(covariance(1, 1), across, 1e-12);
  EXPECT_NEAR(covariance(2, 2), across, 1e-12);
  EXPECT_NEAR(covariance(1, 2), 0.0, 1e-15);
  // Its total: the mean squared displacement, (distance x RMS angle)^2 across two of three axes.
  EXPECT_NEAR(covariance.trace(), std::pow(0.6 * 2.0 * kDegree, 2) * 2.0 / 3.0, 1e-12);
}

TEST(CameraPosePositionCovariance, TheSameWhicheverWayTheCameraLooks) {
  const Eigen::Vector3d oblique = Eigen::Vector3d(0.3, -0.4, 0.5).normalized() * 0.8;
  const Eigen::Matrix3d covariance = cameraPosePositionCovariance(oblique, 1.5, 0.0);
  EXPECT_NEAR((covariance * oblique).norm(), 0.0, 1e-15) << "no variance along the line of sight";
  const Eigen::Vector3d across = oblique.unitOrthogonal();
  EXPECT_NEAR(across.dot(covariance * across), std::pow(0.8 * 1.5 * kDegree, 2) / 3.0, 1e-12);
}

TEST(CameraPosePositionCovariance, AShiftErrorMovesTheObjectByItselfAndAddsToTheRotations) {
  const Eigen::Vector3d offset(0.0, 0.0, 0.7);
  const Eigen::Matrix3d shift = cameraPosePositionCovariance(offset, 0.0, 5.0);
  EXPECT_TRUE(shift.isApprox(std::pow(0.005 / std::sqrt(3.0), 2) * Eigen::Matrix3d::Identity()));
  const Eigen::Matrix3d both = cameraPosePositionCovariance(offset, 2.0, 5.0);
  EXPECT_TRUE(both.isApprox(cameraPosePositionCovariance(offset, 2.0, 0.0) + shift));
  EXPECT_TRUE(cameraPosePositionCovariance(offset, 0.0, 0.0).isZero())
      << "exact camera poses add nothing";
}

TEST(CameraPosePositionCovariance, RefusesNegativeOrNonFiniteErrors) {
  const Eigen::Vector3d offset(0.0, 0.0, 0.6);
  EXPECT_THROW(cameraPosePositionCovariance(offset, -1.0, 0.0), Error);
  EXPECT_THROW(cameraPosePositionCovariance(offset, 0.0, -1.0), Error);
  EXPECT_THROW(cameraPosePositionCovariance(offset, std::nan(""), 0.0), Error);
  EXPECT_THROW(cameraPosePositionCovariance(offset, 0.0, std::numeric_limits<double>::infinity()),
               Error);
}

}  // namespace
}  // namespace vdc
