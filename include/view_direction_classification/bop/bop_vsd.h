#pragma once

#include <vector>

#include "view_direction_classification/bop/bop_depth.h"
#include "view_direction_classification/bop/bop_types.h"
#include "view_direction_classification/geometry/depth_renderer.h"

namespace vdc {

// BOP's Visible Surface Discrepancy (Hodan et al. 2016/2018; bop_toolkit's pose_error.vsd) with
// the package's renderer: the model's depth under the estimate and under the truth is rendered
// with the image's camera; a pixel of the truth's rendering is visible where the image's depth
// is not more than `delta` [mm] in front of it (or missing), a pixel of the estimate's where the
// same holds or the truth's visible surface covers it. Over the union of the two visible masks a
// pixel costs 0 if both renderings are visible there and their depths differ by less than `tau`
// [mm], else 1; the error is the mean cost (1 for an empty union). A missing measurement counts
// as visible, as in BOP's 2019 visibility ("bop19"); depths are along the optical axis, as the
// PNG stores them.
// renderer: the model in metres, with the image's intrinsics. Returns one error per tau.
// Throws vdc::Error if the image's size is not the renderer's.
std::vector<double> visibleSurfaceDiscrepancy(const BopPose& estimate, const BopPose& truth,
                                              const DepthRenderer& renderer,
                                              const BopDepthImage& image, double depth_scale,
                                              const std::vector<double>& taus, double delta = 15.0);

// BOP's VSD thresholds: tau 0.05, 0.10, ..., 0.50 x the diameter [mm] and the correctness
// thresholds on the error 0.05, 0.10, ..., 0.50.
std::vector<double> vsdTaus(double diameter);
std::vector<double> vsdCorrectThresholds();

}  // namespace vdc
