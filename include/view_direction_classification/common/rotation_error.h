#pragma once

#include <Eigen/Core>

#include <vector>

namespace vdc {

// Orientation errors for the evaluation (doc/method.md section 10), in DEGREES (the reports' unit),
// between an estimated and a true orientation given as unit quaternions (w, x, y, z), q ~ -q.
// All throw vdc::Error for non-unit or non-finite quaternions.

// The angle of the rotation between them: 2 arccos |<q_est, q_true>|, in [0, 180].
double rotationErrorDeg(const Eigen::Vector4d& estimate, const Eigen::Vector4d& truth);

// For an object symmetric about `axis` (object frame): the angle between R_est a and R_true a,
// in [0, 180]; rotations about the axis cost nothing. Throws for a zero or non-finite axis.
double axisSymmetricRotationErrorDeg(const Eigen::Vector4d& estimate, const Eigen::Vector4d& truth,
                                     const Eigen::Vector3d& axis);

// For an object with a discrete symmetry group (object-frame rotations g that leave it
// unchanged; the identity is implied): min over g of rotationErrorDeg(estimate, truth (x) g).
double discreteSymmetricRotationErrorDeg(const Eigen::Vector4d& estimate,
                                         const Eigen::Vector4d& truth,
                                         const std::vector<Eigen::Vector4d>& symmetry_group);

}  // namespace vdc
