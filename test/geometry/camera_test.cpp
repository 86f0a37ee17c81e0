#include "view_direction_classification/geometry/camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

TEST(Camera, RandomDirectionsAndRollsRoundTripAndLookAtTheOrigin) {
  std::mt19937 rng(2024);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> roll(-M_PI, M_PI);
  for (int i = 0; i < 500; ++i) {
    const Eigen::Vector3d d = Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
    const double distance = 0.3 + 0.1 * i / 100.0;
    const Eigen::Isometry3d pose = cameraFromObject(d, distance, roll(rng));
    EXPECT_TRUE(viewDirectionOf(pose).isApprox(d, 1e-12));
    EXPECT_TRUE((pose.linear() * d).isApprox(Eigen::Vector3d(0, 0, -1), 1e-12));
    // The object origin sits on the optical axis at the requested distance.
    EXPECT_TRUE(pose.translation().isApprox(Eigen::Vector3d(0, 0, distance), 1e-12));
    EXPECT_NEAR(pose.linear().determinant(), 1.0, 1e-12);
    EXPECT_TRUE((pose.linear() * pose.linear().transpose()).isIdentity(1e-12));
  }
}

TEST(Camera, AtZeroRollObjectUpProjectsToImageUp) {
  const Eigen::Isometry3d pose = cameraFromObject(Eigen::Vector3d(1, 2, 0.5), 0.6, 0.0);
  const Eigen::Vector3d up_in_camera = pose.linear() * Eigen::Vector3d::UnitZ();
  EXPECT_NEAR(up_in_camera.x(), 0.0, 1e-12);
  EXPECT_LT(up_in_camera.y(), 0.0);  // image y grows downwards
}

TEST(Camera, LookingAlongTheZAxisUsesObjectYAsUp) {
  for (const double sign : {1.0, -1.0}) {
    const Eigen::Isometry3d pose = cameraFromObject(Eigen::Vector3d(0, 0, sign), 0.6, 0.0);
    const Eigen::Vector3d y_in_camera = pose.linear() * Eigen::Vector3d::UnitY();
    EXPECT_TRUE(y_in_camera.isApprox(Eigen::Vector3d(0, -1, 0), 1e-12));
    EXPECT_TRUE(viewDirectionOf(pose).isApprox(Eigen::Vector3d(0, 0, sign), 1e-12));
  }
}

TEST(Camera, RollTurnsTheCameraAboutItsOpticalAxis) {
  const Eigen::Vector3d d(0.3, -0.4, 0.2);
  const Eigen::Isometry3d level = cameraFromObject(d, 0.6, 0.0);
  const Eigen::Isometry3d rolled = cameraFromObject(d, 0.6, 0.7);
  const Eigen::Matrix3d expected =
      Eigen::AngleAxisd(-0.7, Eigen::Vector3d::UnitZ()).toRotationMatrix() * level.linear();
  EXPECT_TRUE(rolled.linear().isApprox(expected, 1e-12));
}

TEST(Camera, NonUnitDirectionIsNormalised) {
  const Eigen::Isometry3d a = cameraFromObject(Eigen::Vector3d(0, 3, 4), 0.5, 0.1);
  const Eigen::Isometry3d b = cameraFromObject(Eigen::Vector3d(0, 0.6, 0.8), 0.5, 0.1);
  EXPECT_TRUE(a.isApprox(b, 1e-12));
}

TEST(Camera, BadArgumentsThrow) {
  EXPECT_THROW(cameraFromObject(Eigen::Vector3d::Zero(), 0.6, 0.0), Error);
  EXPECT_THROW(cameraFromObject(Eigen::Vector3d(std::nan(""), 0, 1), 0.6, 0.0), Error);
  EXPECT_THROW(cameraFromObject(Eigen::Vector3d::UnitX(), 0.0, 0.0), Error);
  EXPECT_THROW(cameraFromObject(Eigen::Vector3d::UnitX(), -1.0, 0.0), Error);
  EXPECT_THROW(cameraFromObject(Eigen::Vector3d::UnitX(), 0.6, INFINITY), Error);
  EXPECT_THROW(viewDirectionOf(Eigen::Isometry3d::Identity()), Error);
  CameraIntrinsics bad;
  bad.fx = 0;
  EXPECT_THROW(checkIntrinsics(bad), Error);
  bad = CameraIntrinsics();
  bad.width = 0;
  EXPECT_THROW(checkIntrinsics(bad), Error);
  EXPECT_NO_THROW(checkIntrinsics(CameraIntrinsics()));
}

}  // namespace
}  // namespace vdc
