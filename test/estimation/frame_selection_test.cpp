#include "view_direction_classification/estimation/frame_selection.h"

#include <gtest/gtest.h>

#include <cmath>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

double degrees(double deg) { return deg * M_PI / 180.0; }

TEST(FusedViews, SeparationIsTheAngleToTheNearestFusedDirection) {
  FusedViews views;
  EXPECT_DOUBLE_EQ(views.separationFrom(Eigen::Vector3d(1, 0, 0)), M_PI);
  views.add(Eigen::Vector3d(2, 0, 0));  // normalised
  views.add(Eigen::Vector3d(0, 0, 1));
  EXPECT_EQ(views.size(), 2);
  EXPECT_NEAR(views.directions()[0].norm(), 1.0, 1e-12);
  const Eigen::Vector3d d(std::cos(degrees(10)), std::sin(degrees(10)), 0);
  EXPECT_NEAR(views.separationFrom(3.0 * d), degrees(10), 1e-9);
  EXPECT_NEAR(views.separationFrom(Eigen::Vector3d(0, 1, 0)), degrees(90), 1e-9);
  EXPECT_THROW(views.add(Eigen::Vector3d::Zero()), Error);
  EXPECT_THROW(views.add(Eigen::Vector3d(NAN, 0, 0)), Error);
  views.clear();
  EXPECT_EQ(views.size(), 0);
}

TEST(FrameSelection, LikelihoodExponentGrowsWithSeparationUpToOne) {
  EXPECT_DOUBLE_EQ(likelihoodExponent(0.0, 0.5), 0.0);
  EXPECT_DOUBLE_EQ(likelihoodExponent(0.25, 0.5), 0.5);
  EXPECT_DOUBLE_EQ(likelihoodExponent(0.7, 0.5), 1.0);
  EXPECT_DOUBLE_EQ(likelihoodExponent(0.0, 0.0), 1.0);  // no tempering
}

TEST(FrameSelection, ACameraFasterThanTheLimitsJumpedAndASlowerOneMoved) {
  FrameSelectionParameters limits;  // 2 m/s, 3.14 rad/s
  StampedPose before;
  before.time = 10.0;
  StampedPose after = before;
  after.time = 10.1;
  after.world_from_camera.translation() = Eigen::Vector3d(0.15, 0, 0);  // 1.5 m/s
  EXPECT_FALSE(cameraJumpReason(before, after, limits));
  after.world_from_camera.translation() = Eigen::Vector3d(0.5, 0, 0);  // 5 m/s
  const auto reason = cameraJumpReason(before, after, limits);
  ASSERT_TRUE(reason);
  EXPECT_NE(reason->find("jumped 0.500 m"), std::string::npos) << *reason;
  after.world_from_camera.translation().setZero();
  after.world_from_camera.linear() =
      Eigen::AngleAxisd(0.5, Eigen::Vector3d::UnitY()).toRotationMatrix();  // 5 rad/s
  EXPECT_TRUE(cameraJumpReason(before, after, limits));
  limits.max_camera_turn_rate = 0.0;  // no turn check
  EXPECT_FALSE(cameraJumpReason(before, after, limits));
  after.time = 9.0;  // an older frame is no motion to judge
  EXPECT_FALSE(cameraJumpReason(before, after, FrameSelectionParameters{}));
}

TEST(FrameSelection, RefusesNonFiniteOrNegativeLimits) {
  FrameSelectionParameters p;
  p.min_view_separation = NAN;
  EXPECT_THROW(checkFrameSelectionParameters(p), Error);
  p = {};
  p.max_camera_speed = -1;
  EXPECT_THROW(checkFrameSelectionParameters(p), Error);
  p = {};
  p.min_information_gain = -0.1;
  EXPECT_THROW(checkFrameSelectionParameters(p), Error);
  EXPECT_NO_THROW(checkFrameSelectionParameters({}));
}

}  // namespace
}  // namespace vdc
