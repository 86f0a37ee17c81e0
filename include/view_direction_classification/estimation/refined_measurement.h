#pragma once

#include "view_direction_classification/bingham/bingham_mixture.h"
#include "view_direction_classification/refinement/pose_refiner.h"

namespace vdc {

// How verified poses enter the belief (doc/method.md, "Refinement").
struct RefinedFusionParameters {
  // Concentration of a verified pose's component when the pose carries no rotation covariance
  // from its fit (pose_refiner.h; the refiner gives every kept pose one): exp(-c sin^2(theta/2))
  // halves at theta = 2 asin(sqrt(ln 2 / c)), 4.8 degrees for c = 400.
  double concentration = 400.0;
  // A pose's weight is exp(likelihood_scale * score): a 0.05 better score counts e times more.
  double likelihood_scale = 20.0;
  // Weight of the uniform "none of them" component, so that the belief's other hypotheses
  // survive when every verified pose is wrong.
  double outlier_weight = 0.05;
  // The camera pose's rotation error [deg, RMS angle] that a view's evidence allows for: a pose
  // fitted in a camera frame whose pose is that far off is that far off in the fixed frame,
  // however good the fit. Each verified pose's rotation covariance grows by
  // (camera_pose_uncertainty_deg / sqrt(3))^2 per axis (camera_pose_error.h's noise model).
  // 0: the poses are exact (a simulator's, or a well-calibrated robot's).
  double camera_pose_uncertainty_deg = 0.0;
  // The camera pose's shift error [mm, RMS]. Neither it nor the rotation error above leaves the
  // position alone: each view's refined position covariance grows by what they do to it
  // (camera_pose_covariance.h), so that a robot does not trust a millimetre fit that its tf puts
  // centimetres off. 0 and 0: the fit's covariance alone.
  double camera_pose_uncertainty_mm = 0.0;
  // How far the object's surface may differ from the model's [mm, RMS]: a CAD mesh of a mug
  // another one's glaze made thicker, a scan of another item of the product. The fit places
  // the model's origin off by about that much, so each view's refined position covariance grows
  // by (model_error_mm / sqrt(3))^2 per axis. 0: the mesh is the object.
  double model_error_mm = 0.0;
};

// The verified poses (result.kept and result.alternatives, q_WO) as one measurement over q_WO:
// one concentrated Bingham component per pose, shaped by its fit's rotation covariance (the
// fixed concentration for an alternative, which has none) and left free along its roll sector
// (pose_refiner.h), weighted by its verification likelihood relative to the best kept pose, plus
// the uniform outlier component; multiplying the belief by it keeps the belief one Bingham
// mixture. Throws vdc::Error for no kept poses or invalid parameters
// (concentration or scale <= 0, outlier weight outside (0, 1), a camera pose uncertainty,
// shift or model error negative or not finite).
BinghamMixture refinedMeasurement(const RefinementResult& result,
                                  const RefinedFusionParameters& parameters);

// A measured pose's log weight relative to the best kept pose's, likelihood_scale x (its score -
// the best's): refinedMeasurement's components, and refinedPositionCovariance's spread.
double measurementLogWeight(const RefinedPose& pose, const RefinedPose& best,
                            const RefinedFusionParameters& parameters);

}  // namespace vdc
