#pragma once

// The position a refined view reports, and how far to trust it.

#include <Eigen/Core>

#include "view_direction_classification/estimation/refined_measurement.h"
#include "view_direction_classification/refinement/pose_refiner.h"

namespace vdc {

// The covariance [m^2] of the best kept pose's position (result.kept.front(), whose position the
// estimator reports) as the view's evidence gives it: over the poses that enter the view's
// measurement (kept and alternatives, refinedMeasurement's weights exp(likelihood_scale x
// score), relative to the best), each pose's fit covariance (an alternative's: the best pose's)
// plus the squared offset of its position from the reported one. One pose, or poses at one
// place (turns about a symmetry axis), give the fit's covariance; a view that leaves the mug's
// handle side open (the upside-down twin) puts the other place's offset in it, centimetres, not
// the fit's millimetre. Throws vdc::Error for no kept poses or a non-positive likelihood scale.
Eigen::Matrix3d refinedPositionCovariance(const RefinementResult& result,
                                          const RefinedFusionParameters& parameters);

// What a model that differs from the object adds to it: (model_error_mm / sqrt(3))^2 per axis
// [m^2] (RefinedFusionParameters::model_error_mm). Throws vdc::Error for a negative or
// non-finite error.
Eigen::Matrix3d modelErrorPositionCovariance(double model_error_mm);

}  // namespace vdc
