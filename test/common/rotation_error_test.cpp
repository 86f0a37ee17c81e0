#include "view_direction_classification/common/rotation_error.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/quaternion.h"

#include <gtest/gtest.h>

#include <cmath>

namespace vdc {
namespace {

Eigen::Vector4d about(const Eigen::Vector3d& axis, double degrees) {
  return quaternionFromAxisAngle(axis, degrees * M_PI / 180.0);
}

TEST(RotationError, PlainErrorIsTheRelativeRotationAngleAndIgnoresTheSign) {
  const Eigen::Vector4d truth = about({1, 2, 3}, 40);
  const Eigen::Vector4d estimate = quaternionMultiply(truth, about({0, 1, 0}, 25));
  EXPECT_NEAR(rotationErrorDeg(estimate, truth), 25.0, 1e-9);
  EXPECT_NEAR(rotationErrorDeg(-estimate, truth), 25.0, 1e-9);
  EXPECT_NEAR(rotationErrorDeg(truth, truth), 0.0, 1e-12);
  EXPECT_NEAR(rotationErrorDeg(about({1, 0, 0}, 180), Eigen::Vector4d(1, 0, 0, 0)), 180.0, 1e-9);
  EXPECT_NEAR(rotationErrorDeg(about({1, 0, 0}, 1e-6), Eigen::Vector4d(1, 0, 0, 0)), 1e-6, 1e-15);
}

TEST(RotationError, RotationAboutTheSymmetryAxisCostsNothing) {
  const Eigen::Vector3d axis(0, 0, 1);
  const Eigen::Vector4d truth = about({1, 1, 0}, 30);
  EXPECT_NEAR(
      axisSymmetricRotationErrorDeg(quaternionMultiply(truth, about(axis, 77)), truth, axis), 0.0,
      1e-9);
  EXPECT_NEAR(
      axisSymmetricRotationErrorDeg(quaternionMultiply(truth, about({1, 0, 0}, 20)), truth, axis),
      20.0, 1e-9);
  EXPECT_THROW(axisSymmetricRotationErrorDeg(truth, truth, Eigen::Vector3d::Zero()), Error);
}

TEST(RotationError, DiscreteSymmetryTakesTheClosestGroupElement) {
  // A two-fold symmetry about the object's z axis.
  const std::vector<Eigen::Vector4d> group{about({0, 0, 1}, 180)};
  const Eigen::Vector4d truth = about({1, 0, 0}, 50);
  const Eigen::Vector4d flipped = quaternionMultiply(truth, about({0, 0, 1}, 175));
  EXPECT_NEAR(discreteSymmetricRotationErrorDeg(flipped, truth, group), 5.0, 1e-9);
  EXPECT_NEAR(rotationErrorDeg(flipped, truth), 175.0, 1e-9);
  EXPECT_NEAR(discreteSymmetricRotationErrorDeg(truth, truth, {}), 0.0, 1e-12);
  EXPECT_THROW(discreteSymmetricRotationErrorDeg(truth, truth, {Eigen::Vector4d(2, 0, 0, 0)}),
               Error);
  EXPECT_THROW(rotationErrorDeg(Eigen::Vector4d(NAN, 0, 0, 0), truth), Error);
}

}  // namespace
}  // namespace vdc
