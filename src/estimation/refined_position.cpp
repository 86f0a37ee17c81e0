#include "view_direction_classification/estimation/refined_position.h"

#include <cmath>
#include <string>

#include "view_direction_classification/common/error.h"

namespace vdc {

Eigen::Matrix3d refinedPositionCovariance(const RefinementResult& result,
                                          const RefinedFusionParameters& parameters) {
  if (result.kept.empty()) throw Error("no verified poses to take a position from");
  if (!(parameters.likelihood_scale > 0.0) || !std::isfinite(parameters.likelihood_scale)) {
    throw Error("refinement's fusion likelihood scale must be positive");
  }
  const RefinedPose& reported = result.kept.front();
  const Eigen::Vector3d position = reported.world_from_object.translation();
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  double total = 0.0;
  const auto add = [&](const RefinedPose& pose, const Eigen::Matrix3d& fit) {
    const double weight = std::exp(measurementLogWeight(pose, reported, parameters));
    const Eigen::Vector3d offset = pose.world_from_object.translation() - position;
    covariance += weight * (fit + offset * offset.transpose());
    total += weight;
  };
  for (const RefinedPose& pose : result.kept) add(pose, pose.position_covariance);
  // Alternatives carry no covariance of their own (kept_poses.h): the reported fit's stands.
  for (const RefinedPose& pose : result.alternatives) add(pose, reported.position_covariance);
  return covariance / total;
}

Eigen::Matrix3d modelErrorPositionCovariance(double model_error_mm) {
  if (!(model_error_mm >= 0.0) || !std::isfinite(model_error_mm)) {
    throw Error("the model error must be finite and >= 0, got " + std::to_string(model_error_mm) +
                " mm");
  }
  const double per_axis = model_error_mm / 1000.0 / std::sqrt(3.0);
  return per_axis * per_axis * Eigen::Matrix3d::Identity();
}

}  // namespace vdc
