#include "view_direction_classification/estimation/refined_measurement.h"

#include <gtest/gtest.h>

#include <cmath>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/quaternion.h"

namespace vdc {
namespace {

// A kept pose at a fixed orientation whose sector axis is the object's z.
RefinedPose keptPose(double roll_sector_deg) {
  RefinedPose pose;
  pose.orientation = quaternionFromAxisAngle(Eigen::Vector3d(0.3, -0.5, 0.8).normalized(), 1.1);
  pose.sector_axis = Eigen::Vector3d::UnitZ();
  pose.roll_sector_deg = roll_sector_deg;
  pose.score.inlier_fraction = 0.95;
  return pose;
}

// The measurement's log density at the pose turned by angle_deg about the object's `axis`,
// relative to its density at the pose.
double relativeLogDensity(const RefinedPose& pose, const Eigen::Vector3d& axis, double angle_deg,
                          const RefinedFusionParameters& parameters = {}) {
  RefinementResult result;
  result.kept = {pose};
  const BinghamMixture measurement = refinedMeasurement(result, parameters);
  const Eigen::Vector4d turned =
      quaternionMultiply(pose.orientation, quaternionFromAxisAngle(axis, angle_deg * M_PI / 180));
  return measurement.logDensity(turned) - measurement.logDensity(pose.orientation);
}

TEST(RefinedMeasurement, ASharpPoseFallsOffEquallyAboutEveryAxis) {
  const RefinedPose pose = keptPose(0.0);
  for (const Eigen::Vector3d axis :
       {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ()}) {
    // exp(-400 sin^2(7.5 deg)): 6.8 nats, less the uniform outlier component's floor.
    EXPECT_LT(relativeLogDensity(pose, axis, 15.0), -5.0) << axis.transpose();
  }
}

TEST(RefinedMeasurement, AWholeTurnSectorLeavesTheRollFreeAndTheTiltSharp) {
  const RefinedPose pose = keptPose(180.0);
  for (const double angle : {30.0, 90.0, 180.0}) {
    EXPECT_NEAR(relativeLogDensity(pose, Eigen::Vector3d::UnitZ(), angle), 0.0, 1e-6) << angle;
  }
  EXPECT_LT(relativeLogDensity(pose, Eigen::Vector3d::UnitX(), 15.0), -5.0);
  EXPECT_LT(relativeLogDensity(pose, Eigen::Vector3d::UnitY(), 15.0), -5.0);
}

TEST(RefinedMeasurement, APartialSectorIsOneStandardDeviationOfTheRoll) {
  // 30 degrees: z = 2 / sigma^2 = 7.3, exp(-z sin^2(15 deg)) = exp(-0.49), a Gaussian's
  // exp(-1/2) at one sigma.
  const RefinedPose pose = keptPose(30.0);
  EXPECT_NEAR(relativeLogDensity(pose, Eigen::Vector3d::UnitZ(), 30.0), -0.49, 0.03);
  EXPECT_LT(relativeLogDensity(pose, Eigen::Vector3d::UnitX(), 15.0), -5.0);
}

TEST(RefinedMeasurement, TheFitsRotationCovarianceShapesTheComponent) {
  // sigma 1 degree about x and y, 4 degrees about z: a 2-degree turn costs
  // (2 / sigma)^2 / 2 nats, 2 about x and 0.125 about z.
  RefinedPose pose = keptPose(0.0);
  const double degree = M_PI / 180.0;
  pose.rotation_covariance = Eigen::Vector3d(1.0, 1.0, 16.0).asDiagonal();
  pose.rotation_covariance *= degree * degree;
  EXPECT_NEAR(relativeLogDensity(pose, Eigen::Vector3d::UnitX(), 2.0), -2.0, 0.02);
  EXPECT_NEAR(relativeLogDensity(pose, Eigen::Vector3d::UnitZ(), 2.0), -0.125, 0.01);
  // A roll sector frees z further, never sharpens it: 30 degrees is looser than 4.
  pose.roll_sector_deg = 30.0;
  EXPECT_NEAR(relativeLogDensity(pose, Eigen::Vector3d::UnitZ(), 30.0), -0.49, 0.03);
  pose.roll_sector_deg = 2.0;
  EXPECT_NEAR(relativeLogDensity(pose, Eigen::Vector3d::UnitZ(), 2.0), -0.125, 0.01);
}

TEST(RefinedMeasurement, TheCameraPoseUncertaintyAddsItsVarianceToTheFitsAboutEveryAxis) {
  // The fit's sigma 1 degree per axis; a camera pose uncertainty of 3 degrees RMS is sqrt(3) per
  // axis: sigma^2 = 1 + 3 = 4, a 2-degree turn costs (2 / 2)^2 / 2 = 0.5 nats instead of 2.
  RefinedPose pose = keptPose(0.0);
  const double degree = M_PI / 180.0;
  pose.rotation_covariance = Eigen::Matrix3d::Identity() * degree * degree;
  RefinedFusionParameters parameters;
  parameters.camera_pose_uncertainty_deg = 3.0;
  for (const Eigen::Vector3d axis :
       {Eigen::Vector3d::UnitX(), Eigen::Vector3d::UnitY(), Eigen::Vector3d::UnitZ()}) {
    EXPECT_NEAR(relativeLogDensity(pose, axis, 2.0), -2.0, 0.02) << axis.transpose();
    EXPECT_NEAR(relativeLogDensity(pose, axis, 2.0, parameters), -0.5, 0.01) << axis.transpose();
  }
  // 0 leaves the component exactly as the fit gives it.
  parameters.camera_pose_uncertainty_deg = 0.0;
  EXPECT_EQ(relativeLogDensity(pose, Eigen::Vector3d::UnitX(), 2.0, parameters),
            relativeLogDensity(pose, Eigen::Vector3d::UnitX(), 2.0));
}

TEST(RefinedMeasurement, AnAlternativeEntersWeightedByItsVerificationBesideTheKeptPoses) {
  RefinementResult result;
  result.kept = {keptPose(0.0)};
  RefinedPose twin = keptPose(0.0);
  twin.orientation =
      quaternionMultiply(twin.orientation, quaternionFromAxisAngle(Eigen::Vector3d::UnitX(), M_PI));
  twin.score.inlier_fraction = 0.90;
  const BinghamMixture kept_alone = refinedMeasurement(result, {});
  result.alternatives = {twin};
  const BinghamMixture measurement = refinedMeasurement(result, {});
  // The kept pose, the alternative, the outlier component; 0.05 behind: e^(-20 x 0.05).
  ASSERT_EQ(measurement.components().size(), 3u);
  EXPECT_NEAR(measurement.weight(1) / measurement.weight(0), std::exp(-1.0), 1e-9);
  // Without it the twin had only the outlier's floor; with it, e^-1 of the kept pose's density.
  EXPECT_LT(
      kept_alone.logDensity(twin.orientation) - kept_alone.logDensity(result.kept[0].orientation),
      -10.0);
  EXPECT_NEAR(
      measurement.logDensity(twin.orientation) - measurement.logDensity(result.kept[0].orientation),
      -1.0, 0.01);
}

TEST(RefinedMeasurement, RefusesNoPosesAndInvalidParameters) {
  EXPECT_THROW(refinedMeasurement(RefinementResult{}, RefinedFusionParameters{}), Error);
  RefinementResult result;
  result.kept = {keptPose(0.0)};
  RefinedFusionParameters bad;
  bad.concentration = 0.0;
  EXPECT_THROW(refinedMeasurement(result, bad), Error);
  bad = RefinedFusionParameters{};
  bad.outlier_weight = 1.0;
  EXPECT_THROW(refinedMeasurement(result, bad), Error);
  bad = RefinedFusionParameters{};
  bad.camera_pose_uncertainty_deg = -1.0;
  EXPECT_THROW(refinedMeasurement(result, bad), Error);
  bad.camera_pose_uncertainty_deg = std::nan("");
  EXPECT_THROW(refinedMeasurement(result, bad), Error);
}

}  // namespace
}  // namespace vdc
