#include "view_direction_classification/estimation/refined_position.h"

#include <gtest/gtest.h>

#include <cmath>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

RefinedPose poseAt(const Eigen::Vector3d& position, double inlier_fraction, double fit_sigma) {
  RefinedPose pose;
  pose.world_from_object.translation() = position;
  pose.score.inlier_fraction = inlier_fraction;
  pose.position_covariance = fit_sigma * fit_sigma * Eigen::Matrix3d::Identity();
  return pose;
}

TEST(RefinedPositionCovariance, OnePoseIsItsFitsCovariance) {
  RefinementResult result;
  result.kept = {poseAt(Eigen::Vector3d(0.1, 0.2, 0.3), 0.95, 0.001)};
  EXPECT_TRUE(refinedPositionCovariance(result, {}).isApprox(1e-6 * Eigen::Matrix3d::Identity()));
}

TEST(RefinedPositionCovariance, PosesAtOnePlaceAverageTheirFitsAndAddNoSpread) {
  // Turns about a symmetry axis: one place, two fits.
  RefinementResult result;
  result.kept = {poseAt(Eigen::Vector3d(0.1, 0.2, 0.3), 0.95, 0.001),
                 poseAt(Eigen::Vector3d(0.1, 0.2, 0.3), 0.95, 0.002)};
  EXPECT_TRUE(refinedPositionCovariance(result, {}).isApprox(2.5e-6 * Eigen::Matrix3d::Identity()));
}

TEST(RefinedPositionCovariance, ATwinElsewhereAddsItsOffsetAlongItWeightedByItsVerification) {
  const Eigen::Vector3d here(0.0, 0.0, 0.5), offset(0.04, 0.0, 0.0);
  RefinementResult result;
  result.kept = {poseAt(here, 0.95, 0.001), poseAt(here + offset, 0.95, 0.001)};
  const Eigen::Matrix3d equal = refinedPositionCovariance(result, {});
  // Equally verified: half the squared offset along it, the fit across it.
  EXPECT_NEAR(equal(0, 0), 1e-6 + 0.5 * 0.04 * 0.04, 1e-12);
  EXPECT_NEAR(equal(1, 1), 1e-6, 1e-12);
  EXPECT_NEAR(equal(2, 2), 1e-6, 1e-12);
  // An alternative 0.1 behind (weight exp(-20 x 0.1) under the default scale) counts that much,
  // with the reported pose's fit.
  RefinementResult with_alternative;
  with_alternative.kept = {poseAt(here, 0.95, 0.001)};
  with_alternative.alternatives = {poseAt(here + offset, 0.85, 0.0)};
  const double weight = std::exp(
      RefinedFusionParameters{}.likelihood_scale *
      (with_alternative.alternatives[0].score.score() - with_alternative.kept[0].score.score()));
  ASSERT_LT(weight, 0.5);
  const Eigen::Matrix3d behind = refinedPositionCovariance(with_alternative, {});
  EXPECT_NEAR(behind(0, 0), 1e-6 + weight / (1.0 + weight) * 0.04 * 0.04, 1e-12);
  EXPECT_NEAR(behind(1, 1), 1e-6, 1e-12) << "the alternative has no fit of its own";
}

TEST(RefinedPositionCovariance, NeedsAKeptPoseAndAPositiveScale) {
  EXPECT_THROW(refinedPositionCovariance(RefinementResult(), {}), Error);
  RefinementResult result;
  result.kept = {poseAt(Eigen::Vector3d::Zero(), 0.95, 0.001)};
  RefinedFusionParameters bad;
  bad.likelihood_scale = 0.0;
  EXPECT_THROW(refinedPositionCovariance(result, bad), Error);
}

TEST(ModelErrorPositionCovariance, AnRmsErrorSpreadOverTheThreeAxes) {
  EXPECT_TRUE(modelErrorPositionCovariance(5.0).isApprox(std::pow(0.005, 2) / 3.0 *
                                                         Eigen::Matrix3d::Identity()));
  EXPECT_TRUE(modelErrorPositionCovariance(0.0).isZero());
  EXPECT_THROW(modelErrorPositionCovariance(-1.0), Error);
  EXPECT_THROW(modelErrorPositionCovariance(std::nan("")), Error);
}

}  // namespace
}  // namespace vdc
