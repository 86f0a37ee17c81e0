#include "view_direction_classification/common/quaternion.h"

#include "view_direction_classification/common/error.h"

#include <cmath>
#include <sstream>
#include <string>

namespace vdc {

Eigen::Vector4d quaternionMultiply(const Eigen::Vector4d& p, const Eigen::Vector4d& q) {
  return quaternionLeftMatrix(p) * q;
}

Eigen::Vector4d quaternionConjugate(const Eigen::Vector4d& q) {
  return Eigen::Vector4d(q(0), -q(1), -q(2), -q(3));
}

Eigen::Matrix4d quaternionLeftMatrix(const Eigen::Vector4d& q) {
  const double w = q(0), x = q(1), y = q(2), z = q(3);
  Eigen::Matrix4d m;
  m << w, -x, -y, -z,  //
      x, w, -z, y,     //
      y, z, w, -x,     //
      z, -y, x, w;
  return m;
}

Eigen::Matrix4d quaternionRightMatrix(const Eigen::Vector4d& q) {
  const double w = q(0), x = q(1), y = q(2), z = q(3);
  Eigen::Matrix4d m;
  m << w, -x, -y, -z,  //
      x, w, z, -y,     //
      y, -z, w, x,     //
      z, y, -x, w;
  return m;
}

bool isUnitQuaternion(const Eigen::Vector4d& q, double tolerance) {
  return q.allFinite() && std::abs(q.norm() - 1.0) <= tolerance;
}

void checkUnitQuaternion(const Eigen::Vector4d& q, const char* what) {
  if (!isUnitQuaternion(q)) {
    std::ostringstream message;
    message << "The quaternion " << what << " (" << q.transpose()
            << ") must be finite with unit norm, but its norm is " << q.norm() << ".";
    throw Error(message.str());
  }
}

Eigen::Quaterniond toEigenQuaternion(const Eigen::Vector4d& q) {
  checkUnitQuaternion(q, "to convert");
  return Eigen::Quaterniond(q(0), q(1), q(2), q(3));
}

Eigen::Vector4d fromEigenQuaternion(const Eigen::Quaterniond& q) {
  const Eigen::Vector4d result(q.w(), q.x(), q.y(), q.z());
  checkUnitQuaternion(result, "to convert");
  return result;
}

Eigen::Matrix3d quaternionToRotationMatrix(const Eigen::Vector4d& q) {
  return toEigenQuaternion(q).toRotationMatrix();
}

Eigen::Vector4d quaternionFromRotationMatrix(const Eigen::Matrix3d& rotation) {
  if (!rotation.allFinite() ||
      !(rotation.transpose() * rotation).isApprox(Eigen::Matrix3d::Identity(), 1e-6) ||
      rotation.determinant() < 0.0) {
    throw Error("The matrix to convert to a quaternion is not a rotation matrix.");
  }
  Eigen::Quaterniond q(rotation);
  q.normalize();
  return fromEigenQuaternion(q);
}

Eigen::Vector4d quaternionFromAxisAngle(const Eigen::Vector3d& axis, double angle) {
  if (!axis.allFinite() || !std::isfinite(angle) || axis.norm() == 0.0) {
    throw Error("A rotation axis must be finite and non-zero, and its angle finite.");
  }
  const Eigen::Vector3d unit = axis.normalized();
  const double s = std::sin(angle / 2.0);
  return Eigen::Vector4d(std::cos(angle / 2.0), s * unit.x(), s * unit.y(), s * unit.z());
}

Eigen::Vector3d rotateVector(const Eigen::Vector4d& q, const Eigen::Vector3d& v) {
  return toEigenQuaternion(q) * v;
}

}  // namespace vdc
