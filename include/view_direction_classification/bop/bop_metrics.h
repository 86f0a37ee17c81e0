#pragma once

#include <Eigen/Core>

#include <vector>

#include "view_direction_classification/bop/bop_types.h"
#include "view_direction_classification/geometry/camera.h"

namespace vdc {

// BOP's pose errors (Hodan et al., "BOP Challenge 2020"; bop_toolkit's pose_error.py) and their
// recall, all in the format's units (mm, pixels).

// The transformations that leave the model's surface unchanged: the identity, each discrete
// symmetry, and each continuous one discretised into ceil(pi / max_step) rotations about its
// axis (max_step: BOP's 0.01, a step below 1 % of the diameter at the rim). Discrete symmetries
// compose with every discretised continuous one (s_c * s_d), as BOP combines them; the
// discretisation includes the zero angle, so the identity is always in the list.
std::vector<BopPose> bopSymmetryTransformations(const BopModelInfo& info, double max_step = 0.01);

// MSSD: the minimum over the symmetries S of the maximum distance [mm] between a model vertex
// under the estimate and under the truth composed with S. vertices [mm]. Empty vertices: 0.
double maximumSymmetryAwareSurfaceDistance(const BopPose& estimate, const BopPose& truth,
                                           const std::vector<Eigen::Vector3d>& vertices,
                                           const std::vector<BopPose>& symmetries);

// MSPD: as MSSD with the distance [px] between the vertices' projections with `camera`.
double maximumSymmetryAwareProjectionDistance(const BopPose& estimate, const BopPose& truth,
                                              const std::vector<Eigen::Vector3d>& vertices,
                                              const std::vector<BopPose>& symmetries,
                                              const CameraIntrinsics& camera);

// BOP's thresholds: MSSD 0.05, 0.10, ..., 0.50 times the diameter [mm]; MSPD 5, 10, ..., 50 px
// times image width / 640.
std::vector<double> mssdThresholds(double diameter);
std::vector<double> mspdThresholds(int image_width);

// The recall averaged over thresholds: for each threshold, the fraction of the `targets`
// instances whose error is at most it (errors: one per matched instance; instances without an
// estimate count as misses), then the mean over thresholds. 0 for targets <= 0.
double averageRecall(const std::vector<double>& errors, int targets,
                     const std::vector<double>& thresholds);

}  // namespace vdc
