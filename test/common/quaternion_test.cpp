#include "view_direction_classification/common/quaternion.h"
#include "view_direction_classification/common/error.h"

#include <gtest/gtest.h>

#include <cmath>

namespace vdc {
namespace {

TEST(Quaternion, MultiplyMatchesEigenComposition) {
  const Eigen::Vector4d p = quaternionFromAxisAngle(Eigen::Vector3d(1, 2, 3), 0.7);
  const Eigen::Vector4d q = quaternionFromAxisAngle(Eigen::Vector3d(-1, 0.5, 2), 1.9);
  const Eigen::Quaterniond expected = toEigenQuaternion(p) * toEigenQuaternion(q);
  EXPECT_TRUE(quaternionMultiply(p, q).isApprox(fromEigenQuaternion(expected), 1e-12));
}

TEST(Quaternion, LeftAndRightMatricesMultiplyFromTheirSide) {
  const Eigen::Vector4d p = quaternionFromAxisAngle(Eigen::Vector3d(0, 1, 3), -0.4);
  const Eigen::Vector4d q = quaternionFromAxisAngle(Eigen::Vector3d(2, 1, 0), 2.5);
  EXPECT_TRUE((quaternionLeftMatrix(p) * q).isApprox(quaternionMultiply(p, q), 1e-12));
  EXPECT_TRUE((quaternionRightMatrix(q) * p).isApprox(quaternionMultiply(p, q), 1e-12));
  EXPECT_TRUE((quaternionLeftMatrix(p).transpose() * quaternionLeftMatrix(p))
                  .isApprox(Eigen::Matrix4d::Identity(), 1e-12));
}

TEST(Quaternion, ConjugateInvertsAUnitQuaternion) {
  const Eigen::Vector4d q = quaternionFromAxisAngle(Eigen::Vector3d(1, -1, 1), 1.1);
  EXPECT_TRUE(
      quaternionMultiply(q, quaternionConjugate(q)).isApprox(Eigen::Vector4d(1, 0, 0, 0), 1e-12));
}

TEST(Quaternion, RotationMatrixRoundTripAndVectorRotation) {
  const Eigen::Vector4d q = quaternionFromAxisAngle(Eigen::Vector3d(0, 0, 1), M_PI / 2);
  EXPECT_TRUE(rotateVector(q, Eigen::Vector3d(1, 0, 0)).isApprox(Eigen::Vector3d(0, 1, 0), 1e-12));
  const Eigen::Vector4d back = quaternionFromRotationMatrix(quaternionToRotationMatrix(q));
  EXPECT_NEAR(std::abs(back.dot(q)), 1.0, 1e-12);
}

TEST(Quaternion, IsUnitQuaternionAcceptsNormsWithinTheToleranceOnly) {
  const Eigen::Vector4d q = Eigen::Vector4d(1, 2, 3, 4).normalized();
  EXPECT_TRUE(isUnitQuaternion(q));
  EXPECT_TRUE(isUnitQuaternion((1.0 + 0.9e-6) * q));
  EXPECT_FALSE(isUnitQuaternion((1.0 + 1.1e-6) * q));
  EXPECT_FALSE(isUnitQuaternion((1.0 - 1.1e-6) * q));
  // A request's looser tolerance: four typed decimals pass, a wrong component does not.
  const Eigen::Vector4d typed(0.7071, 0, 0, 0.7071);
  EXPECT_FALSE(isUnitQuaternion(typed));
  EXPECT_TRUE(isUnitQuaternion(typed, kRequestQuaternionTolerance));
  EXPECT_FALSE(
      isUnitQuaternion(Eigen::Vector4d(0.7071, 0, 0.1, 0.7071), kRequestQuaternionTolerance));
  EXPECT_FALSE(isUnitQuaternion(Eigen::Vector4d(NAN, 0, 0, 0), kRequestQuaternionTolerance));
  EXPECT_FALSE(isUnitQuaternion(Eigen::Vector4d(INFINITY, 0, 0, 0), 1e300));
}

TEST(Quaternion, RejectsNonUnitAndNonFiniteInput) {
  EXPECT_THROW(toEigenQuaternion(Eigen::Vector4d(1, 1, 0, 0)), Error);
  EXPECT_THROW(checkUnitQuaternion(Eigen::Vector4d(NAN, 0, 0, 0), "q"), Error);
  EXPECT_THROW(quaternionFromAxisAngle(Eigen::Vector3d::Zero(), 1.0), Error);
  EXPECT_THROW(quaternionFromRotationMatrix(2.0 * Eigen::Matrix3d::Identity()), Error);
}

}  // namespace
}  // namespace vdc
