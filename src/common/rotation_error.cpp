#include "view_direction_classification/common/rotation_error.h"

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/quaternion.h"

#include <algorithm>
#include <cmath>

namespace vdc {
namespace {

constexpr double kDegreesPerRadian = 180.0 / M_PI;

}  // namespace

double rotationErrorDeg(const Eigen::Vector4d& estimate, const Eigen::Vector4d& truth) {
  checkUnitQuaternion(estimate, "of the estimated orientation");
  checkUnitQuaternion(truth, "of the true orientation");
  // 2 atan2(|vec|, |w|) of the relative rotation equals 2 arccos|<q1,q2>| but keeps full
  // precision for small angles, where arccos near 1 loses half the digits.
  const Eigen::Vector4d relative =
      quaternionMultiply(quaternionConjugate(truth.normalized()), estimate.normalized());
  return 2.0 * std::atan2(relative.tail<3>().norm(), std::abs(relative(0))) * kDegreesPerRadian;
}

double axisSymmetricRotationErrorDeg(const Eigen::Vector4d& estimate, const Eigen::Vector4d& truth,
                                     const Eigen::Vector3d& axis) {
  if (!axis.allFinite() || axis.norm() == 0.0) {
    throw Error("The symmetry axis of an object must be finite and non-zero.");
  }
  const Eigen::Vector3d a = axis.normalized();
  const Eigen::Vector3d estimated = rotateVector(estimate, a);
  const Eigen::Vector3d true_axis = rotateVector(truth, a);
  return std::atan2(estimated.cross(true_axis).norm(), estimated.dot(true_axis)) *
         kDegreesPerRadian;
}

double discreteSymmetricRotationErrorDeg(const Eigen::Vector4d& estimate,
                                         const Eigen::Vector4d& truth,
                                         const std::vector<Eigen::Vector4d>& symmetry_group) {
  double best = rotationErrorDeg(estimate, truth);
  for (const Eigen::Vector4d& g : symmetry_group) {
    checkUnitQuaternion(g, "of a symmetry group element");
    best = std::min(best, rotationErrorDeg(estimate, quaternionMultiply(truth, g).normalized()));
  }
  return best;
}

}  // namespace vdc
