#include "view_direction_classification/estimation/refined_measurement.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/quaternion.h"

namespace vdc {

namespace {

// The exponent of a pose's component: exp(-c sin^2(theta/2)) in each of the three directions of
// a turn theta about the object's axes, except about its sector axis, where the concentration
// z = 2 / sigma^2 makes the roll sector one standard deviation (none for a whole turn). A
// Bingham concentration z is a Gaussian's 2 / sigma^2: sin^2(theta / 2) ~ theta^2 / 4.
Eigen::Matrix4d poseExponent(const RefinedPose& pose, double concentration) {
  const Eigen::Vector4d& q = pose.orientation;
  if (!(pose.roll_sector_deg > 0.0)) return concentration * q * q.transpose();
  const Eigen::Vector3d axis = pose.sector_axis.normalized();
  const Eigen::Vector3d first = axis.unitOrthogonal(), second = axis.cross(first);
  const auto turnDirection = [&](const Eigen::Vector3d& v) {
    return quaternionMultiply(q, Eigen::Vector4d(0.0, v.x(), v.y(), v.z()));
  };
  const double sigma = pose.roll_sector_deg * M_PI / 180.0;
  const double about_axis =
      pose.roll_sector_deg >= 180.0 ? 0.0 : std::min(concentration, 2.0 / (sigma * sigma));
  Eigen::Matrix4d exponent = Eigen::Matrix4d::Zero();
  for (const Eigen::Vector3d& v : {first, second}) {
    const Eigen::Vector4d d = turnDirection(v);
    exponent -= concentration * d * d.transpose();
  }
  const Eigen::Vector4d d = turnDirection(axis);
  return exponent - about_axis * d * d.transpose();
}

}  // namespace

BinghamMixture refinedMeasurement(const RefinementResult& result,
                                  const RefinedFusionParameters& parameters) {
  if (!(parameters.concentration > 0.0) || !std::isfinite(parameters.concentration) ||
      !(parameters.likelihood_scale > 0.0) || !std::isfinite(parameters.likelihood_scale)) {
    throw Error("refinement's fusion concentration and likelihood scale must be positive");
  }
  if (!(parameters.outlier_weight > 0.0 && parameters.outlier_weight < 1.0)) {
    throw Error("refinement's outlier weight must be in (0, 1), got " +
                std::to_string(parameters.outlier_weight));
  }
  if (result.kept.empty()) throw Error("no verified poses to fuse");
  std::vector<double> log_weights;
  std::vector<BinghamDistribution> components;
  double total = 0.0;
  const double best = result.kept.front().score.score();
  for (const RefinedPose& pose : result.kept) {
    components.push_back(
        BinghamDistribution::fromExponentMatrix(poseExponent(pose, parameters.concentration)));
    log_weights.push_back(parameters.likelihood_scale * (pose.score.score() - best));
    total += std::exp(log_weights.back());
  }
  // The outlier share of the whole measurement's mass.
  log_weights.push_back(
      std::log(parameters.outlier_weight / (1.0 - parameters.outlier_weight) * total));
  components.emplace_back();
  return BinghamMixture::fromLogWeights(log_weights, std::move(components));
}

}  // namespace vdc
