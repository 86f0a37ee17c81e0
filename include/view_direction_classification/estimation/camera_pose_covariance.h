#pragma once

// What an uncertain camera pose does to an object's position: a pose fitted to a view is fitted
// in the camera's frame, and the camera's pose from tf (hand-eye calibration, arm kinematics)
// carries it into the fixed frame with that pose's error, however good the fit.

#include <Eigen/Core>

namespace vdc {

// The covariance [m^2] that the camera pose's error adds to the position of an object at
// `camera_to_object` [m] from the camera (fixed frame), with the error model of
// evaluation/camera_pose_error.h: a rotation of RMS angle rotation_deg (per axis
// (rotation_deg / sqrt(3))^2) moves the object by omega x camera_to_object, whose covariance is
// s^2 (d^2 I - camera_to_object camera_to_object^T): across the line of sight only, 10.5 mm per
// degree at 0.6 m; a shift of RMS shift_mm moves it by itself, (shift_mm / sqrt(3))^2 per axis.
// Zero for zero errors. Throws vdc::Error for a negative or non-finite error.
Eigen::Matrix3d cameraPosePositionCovariance(const Eigen::Vector3d& camera_to_object,
                                             double rotation_deg, double shift_mm);

}  // namespace vdc
