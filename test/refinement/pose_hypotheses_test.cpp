#include "view_direction_classification/refinement/pose_hypotheses.h"

#include <gtest/gtest.h>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/quaternion.h"
#include "view_direction_classification/common/rotation_error.h"
#include "view_direction_classification/estimation/view_measurement.h"

namespace vdc {
namespace {

BinghamDistribution concentratedAt(const Eigen::Vector4d& q, double concentration = 200.0) {
  return BinghamDistribution::fromExponentMatrix(concentration * q * q.transpose());
}

TEST(OrientationHypotheses, AConcentratedComponentGivesItsMode) {
  const Eigen::Vector4d q = quaternionFromAxisAngle(Eigen::Vector3d(1, 2, 3), 0.7);
  const auto starts = orientationHypotheses(BinghamMixture({1.0}, {concentratedAt(q)}), {});
  ASSERT_EQ(starts.size(), 1u);
  EXPECT_LT(rotationErrorDeg(starts[0].orientation, q), 1e-6);
}

TEST(OrientationHypotheses, AGirdleGivesItsCircleEveryStep) {
  // A view's girdle: every roll about the line of sight, 24 of them 15 degrees apart.
  const Eigen::Vector3d direction = Eigen::Vector3d(0.3, 1.0, 0.4).normalized();
  const BinghamMixture girdle({1.0}, {viewGirdle(direction, 18.0)});
  HypothesisParameters parameters;
  parameters.girdle_step_deg = 15.0;
  const auto starts = orientationHypotheses(girdle, parameters);
  ASSERT_EQ(starts.size(), 24u);
  for (std::size_t i = 0; i < starts.size(); ++i) {
    // Each shows the object from `direction` ...
    const Eigen::Vector3d seen = rotateVector(starts[i].orientation, direction);
    EXPECT_NEAR(seen.z(), -1.0, 1e-9);
    // ... and neighbours differ by the step.
    const auto& next = starts[(i + 1) % starts.size()].orientation;
    EXPECT_NEAR(rotationErrorDeg(starts[i].orientation, next), 15.0, 1e-6);
  }
}

TEST(OrientationHypotheses, TakesTheHeaviestComponentsAboveTheWeightFloor) {
  const Eigen::Vector4d a = quaternionFromAxisAngle(Eigen::Vector3d::UnitX(), 0.5);
  const Eigen::Vector4d b = quaternionFromAxisAngle(Eigen::Vector3d::UnitY(), 1.0);
  const Eigen::Vector4d c = quaternionFromAxisAngle(Eigen::Vector3d::UnitZ(), 1.5);
  const BinghamMixture belief({0.2, 0.79995, 0.00005},
                              {concentratedAt(a), concentratedAt(b), concentratedAt(c)});
  HypothesisParameters parameters;
  parameters.min_relative_weight = 1e-3;
  const auto starts = orientationHypotheses(belief, parameters);
  ASSERT_EQ(starts.size(), 2u);
  EXPECT_EQ(starts[0].component, 1);
  EXPECT_EQ(starts[1].component, 0);
  parameters.max_components = 1;
  EXPECT_EQ(orientationHypotheses(belief, parameters).size(), 1u);
}

TEST(OrientationHypotheses, RefusesInvalidParameters) {
  HypothesisParameters parameters;
  parameters.girdle_step_deg = 0.0;
  EXPECT_THROW(orientationHypotheses(BinghamMixture(), parameters), Error);
  parameters = {};
  parameters.max_components = 0;
  EXPECT_THROW(orientationHypotheses(BinghamMixture(), parameters), Error);
}

}  // namespace
}  // namespace vdc
