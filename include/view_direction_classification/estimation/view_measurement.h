#pragma once

#include "view_direction_classification/bingham/bingham.h"
#include "view_direction_classification/bingham/bingham_mixture.h"

#include <Eigen/Core>

#include <vector>

namespace vdc {

// The measurement model of doc/method.md section 8: a viewing direction fixes two of the three
// rotational degrees of freedom, so the orientations q_CO that show the object from direction d
// form a great circle on S^3, q(t) = (rotation by t about the optical axis) (x) a. Its likelihood
// is a girdle Bingham.

// One q_CO with R_CO d = (0, 0, -1), i.e. the object seen from direction d (unit vector in the
// object frame from the object origin towards the camera): the smallest rotation taking d onto
// the camera's -z axis. Throws vdc::Error for a non-finite or non-unit d (tolerance 1e-6).
Eigen::Vector4d orientationSeenFrom(const Eigen::Vector3d& direction);

// The girdle of direction d: mode a = orientationSeenFrom(d), axes i (x) a, j (x) a, k (x) a with
// concentrations (-kappa, -kappa, -roll_concentration). Tilting the object by theta away from d
// lowers the density by exp(-kappa sin^2(theta/2)); the roll about the optical axis is left
// (nearly) free because FPFH is roll-invariant. Throws vdc::Error for kappa <= 0 or a negative
// or non-finite roll concentration.
BinghamDistribution viewGirdle(const Eigen::Vector3d& direction, double kappa,
                               double roll_concentration = 0.0);

// The default kappa: at half the spacing between neighbouring directions the tilt density
// exp(-kappa sin^2(theta/2)) is still 1/sqrt(2) of its peak: kappa = ln 2 / (2 sin^2(spacing/4)),
// about 18 for the 42-direction icosphere (spacing ~ 31.7 deg). The starting point was half
// height at half the spacing (twice this kappa); the evaluation (default mug model, 16 x 12
// views) prefers the broader girdles: median error after 5 views 8.2 vs 11.0 deg unoccluded,
// 10.1 vs 12.6 deg at r_vis 5 cm; narrower ones (74, 150) are worse still. Throws vdc::Error
// unless 0 < spacing <= pi.
double defaultViewConcentration(double neighbour_spacing);

// The view distribution sharpened (exponent > 1) or flattened (< 1): p_sum(m)^exponent,
// renormalised; exponent 1 returns p_sum unchanged. The classifier's averaged p_sum spreads over
// many neighbouring directions, which makes the belief wider than its errors (doc/evaluation.md,
// "Camera streams and calibration"); an exponent on p_sum alone narrows it without narrowing each
// girdle. Throws vdc::Error for an empty p_sum, negative or non-finite entries, or an exponent
// that is not finite and positive.
Eigen::VectorXd sharpenedDistribution(const Eigen::VectorXd& p_sum, double exponent);

// The view's measurement sum_m p_sum(m) B_m in the camera frame: one girdle per direction whose
// probability is at least min_weight (1e-3; if none is, the most probable one alone), weights
// renormalised. Throws vdc::Error if p_sum and directions differ in size or are empty, p_sum has
// negative or non-finite entries or does not sum to 1 (tolerance 1e-6), or a direction is not
// unit.
BinghamMixture viewMeasurement(const Eigen::VectorXd& p_sum,
                               const std::vector<Eigen::Vector3d>& directions, double kappa,
                               double roll_concentration = 0.0, double min_weight = 1e-3);

// A camera-frame belief about q_CO as a belief about q_WO = q_WC (x) q_CO in the fixed frame:
// every axis left-multiplied by q_WC (the camera pose from tf). Throws vdc::Error for a non-unit
// q_WC.
BinghamMixture cameraToFixedFrame(const BinghamMixture& camera_frame, const Eigen::Vector4d& q_WC);

}  // namespace vdc
