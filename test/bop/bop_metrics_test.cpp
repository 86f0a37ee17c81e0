#include "view_direction_classification/bop/bop_metrics.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <vector>

namespace vdc {
namespace {

// A box's corners [mm], 100 x 60 x 40, centred on the origin.
std::vector<Eigen::Vector3d> boxCorners() {
  std::vector<Eigen::Vector3d> corners;
  for (int i = 0; i < 8; ++i) {
    corners.emplace_back((i & 1) ? 50 : -50, (i & 2) ? 30 : -30, (i & 4) ? 20 : -20);
  }
  return corners;
}

BopPose at(const Eigen::Matrix3d& R, const Eigen::Vector3d& t) { return {R, t}; }

Eigen::Matrix3d turnZ(double angle) {
  return Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

const CameraIntrinsics kCamera{640, 480, 500, 500, 320, 240};

TEST(BopMetrics, IdenticalPosesHaveNoError) {
  const BopPose pose = at(turnZ(0.4), {10, -20, 800});
  const auto symmetries = bopSymmetryTransformations({});
  EXPECT_EQ(maximumSymmetryAwareSurfaceDistance(pose, pose, boxCorners(), symmetries), 0.0);
  EXPECT_EQ(maximumSymmetryAwareProjectionDistance(pose, pose, boxCorners(), symmetries, kCamera),
            0.0);
}

TEST(BopMetrics, TranslationIsTheSurfaceErrorAndItsProjection) {
  const BopPose truth = at(Eigen::Matrix3d::Identity(), {0, 0, 1000});
  const BopPose estimate = at(Eigen::Matrix3d::Identity(), {3, 4, 1000});
  const auto symmetries = bopSymmetryTransformations({});
  EXPECT_NEAR(maximumSymmetryAwareSurfaceDistance(estimate, truth, boxCorners(), symmetries), 5.0,
              1e-12);
  // Every corner moves by 5 mm sideways; the nearest corners (z = 980 mm) move most on the image:
  // 500 px * 5 mm / 980 mm.
  EXPECT_NEAR(
      maximumSymmetryAwareProjectionDistance(estimate, truth, boxCorners(), symmetries, kCamera),
      500.0 * 5.0 / 980.0, 1e-9);
}

TEST(BopMetrics, HalfTurnOfABoxIsAnErrorUnlessItIsASymmetry) {
  const BopPose truth = at(Eigen::Matrix3d::Identity(), {0, 0, 1000});
  const BopPose turned = at(turnZ(M_PI), {0, 0, 1000});
  // Without symmetries: each corner goes to its opposite in x and y: 2 * |(50, 30)|.
  EXPECT_NEAR(maximumSymmetryAwareSurfaceDistance(turned, truth, boxCorners(),
                                                  bopSymmetryTransformations({})),
              2.0 * std::hypot(50.0, 30.0), 1e-9);
  BopModelInfo info;
  info.diameter = 2.0 * std::sqrt(50.0 * 50 + 30 * 30 + 20 * 20);
  info.symmetries_discrete.push_back(at(turnZ(M_PI), Eigen::Vector3d::Zero()));
  const auto symmetries = bopSymmetryTransformations(info);
  EXPECT_EQ(symmetries.size(), 2u);
  EXPECT_NEAR(maximumSymmetryAwareSurfaceDistance(turned, truth, boxCorners(), symmetries), 0.0,
              1e-9);
  EXPECT_NEAR(
      maximumSymmetryAwareProjectionDistance(turned, truth, boxCorners(), symmetries, kCamera), 0.0,
      1e-9);
}

TEST(BopMetrics, SymmetryActsInTheModelFrameBeforeTheTruePose) {
  // The box centred at (10, 0, 0) of its frame: its half-turn about z through its centre is
  // x -> Rz(pi) x + (20, 0, 0). The truth is turned and shifted, so applying the symmetry
  // after the pose instead of before it would not give the symmetric pose.
  std::vector<Eigen::Vector3d> corners = boxCorners();
  for (Eigen::Vector3d& corner : corners) corner.x() += 10;
  BopModelInfo info;
  info.diameter = 123;
  info.symmetries_discrete.push_back(at(turnZ(M_PI), {20, 0, 0}));
  const BopPose truth =
      at(Eigen::AngleAxisd(0.5, Eigen::Vector3d(1, 2, 0).normalized()).toRotationMatrix(),
         {30, -20, 900});
  const BopPose symmetric =
      at(truth.R * turnZ(M_PI), truth.R * Eigen::Vector3d(20, 0, 0) + truth.t);
  const auto symmetries = bopSymmetryTransformations(info);
  EXPECT_NEAR(maximumSymmetryAwareSurfaceDistance(symmetric, truth, corners, symmetries), 0.0,
              1e-9);
  EXPECT_NEAR(
      maximumSymmetryAwareProjectionDistance(symmetric, truth, corners, symmetries, kCamera), 0.0,
      1e-9);
  EXPECT_GT(maximumSymmetryAwareSurfaceDistance(symmetric, truth, corners,
                                                bopSymmetryTransformations({})),
            50.0);
}

TEST(BopMetrics, ContinuousSymmetryLeavesOnlyTheDiscretisationStep) {
  // A ring of points about an axis through (0, 10, 0) along z: any turn about it is a symmetry.
  std::vector<Eigen::Vector3d> ring;
  for (int i = 0; i < 36; ++i) {
    const double a = i * M_PI / 18;
    ring.emplace_back(40 * std::cos(a), 10 + 40 * std::sin(a), 0);
  }
  BopModelInfo info;
  info.diameter = 80;
  info.symmetries_continuous.push_back({Eigen::Vector3d::UnitZ(), {0, 10, 0}});
  const auto symmetries = bopSymmetryTransformations(info);
  EXPECT_EQ(symmetries.size(), 315u);  // ceil(pi / 0.01)
  const BopPose truth = at(Eigen::Matrix3d::Identity(), {0, 0, 500});
  // The turn by 1 rad about the offset axis, which BOP's steps of 2 pi / 315 do not hit.
  BopPose estimate;
  estimate.R = turnZ(1.0);
  estimate.t = Eigen::Vector3d(0, 10, 0) - estimate.R * Eigen::Vector3d(0, 10, 0) + truth.t;
  const double error = maximumSymmetryAwareSurfaceDistance(estimate, truth, ring, symmetries);
  // The nearest step is at most half a step away: a chord of 40 mm * (pi / 315).
  EXPECT_LT(error, 40.0 * M_PI / 315.0 + 1e-9);
  EXPECT_GT(
      maximumSymmetryAwareSurfaceDistance(estimate, truth, ring, bopSymmetryTransformations({})),
      30.0);
}

TEST(BopMetrics, ThresholdsAreBopsAndScaleWithTheImage) {
  const auto mssd = mssdThresholds(200.0);
  ASSERT_EQ(mssd.size(), 10u);
  EXPECT_NEAR(mssd.front(), 10.0, 1e-12);
  EXPECT_NEAR(mssd.back(), 100.0, 1e-12);
  const auto mspd = mspdThresholds(1280);
  ASSERT_EQ(mspd.size(), 10u);
  EXPECT_NEAR(mspd.front(), 10.0, 1e-12);
  EXPECT_NEAR(mspd.back(), 100.0, 1e-12);
}

TEST(BopMetrics, RecallAveragesOverThresholdsAndCountsMissingEstimates) {
  const std::vector<double> thresholds{1, 2, 3, 4};
  // Errors 0.5 (correct at all four), 2.5 (at 3 and 4); the third target has no estimate.
  EXPECT_NEAR(averageRecall({0.5, 2.5}, 3, thresholds), (1.0 / 3 * 2 + 2.0 / 3 * 2) / 4, 1e-12);
  EXPECT_EQ(averageRecall({}, 2, thresholds), 0.0);
  EXPECT_EQ(averageRecall({0.1}, 0, thresholds), 0.0);
}

}  // namespace
}  // namespace vdc
