#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace vdc {

// Quaternions in the core are Eigen::Vector4d in (w, x, y, z) order, so that they live directly in
// R^4 where the Bingham distribution is defined; q and -q are the same rotation. These helpers
// keep the (w,x,y,z) order in one place instead of converting through Eigen::Quaterniond, whose
// coeffs() use (x,y,z,w).

// Hamilton product p (x) q: the rotation q followed by p.
Eigen::Vector4d quaternionMultiply(const Eigen::Vector4d& p, const Eigen::Vector4d& q);

// (w, -x, -y, -z): the inverse of a unit quaternion.
Eigen::Vector4d quaternionConjugate(const Eigen::Vector4d& q);

// The 4x4 matrix L(q) with L(q) p = q (x) p. It is orthogonal for unit q, which is why rotating a
// Bingham distribution is just a change of its axes.
Eigen::Matrix4d quaternionLeftMatrix(const Eigen::Vector4d& q);

// The 4x4 matrix R(q) with R(q) p = p (x) q.
Eigen::Matrix4d quaternionRightMatrix(const Eigen::Vector4d& q);

// Conversions to and from Eigen's types. Throws vdc::Error for non-finite or non-unit input
// (tolerance 1e-6 on the norm).
Eigen::Quaterniond toEigenQuaternion(const Eigen::Vector4d& q);
Eigen::Vector4d fromEigenQuaternion(const Eigen::Quaterniond& q);
Eigen::Matrix3d quaternionToRotationMatrix(const Eigen::Vector4d& q);
Eigen::Vector4d quaternionFromRotationMatrix(const Eigen::Matrix3d& rotation);

// The unit quaternion of a rotation by `angle` radians about `axis` (need not be unit length,
// must be non-zero).
Eigen::Vector4d quaternionFromAxisAngle(const Eigen::Vector3d& axis, double angle);

// Rotates the vector v by the unit quaternion q.
Eigen::Vector3d rotateVector(const Eigen::Vector4d& q, const Eigen::Vector3d& v);

// The one unit-quaternion test of the package, core and ROS shell alike. Two tolerances on |q|:
// the core's, which its own arithmetic keeps, and a request's, for poses a user types into a
// service call with three or four decimals (the caller normalises what it accepts).
constexpr double kUnitQuaternionTolerance = 1e-6;
constexpr double kRequestQuaternionTolerance = 1e-3;

// Whether q is finite with | |q| - 1 | <= tolerance.
bool isUnitQuaternion(const Eigen::Vector4d& q, double tolerance = kUnitQuaternionTolerance);

// Throws vdc::Error naming `what` unless isUnitQuaternion(q).
void checkUnitQuaternion(const Eigen::Vector4d& q, const char* what);

}  // namespace vdc
