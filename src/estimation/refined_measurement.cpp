#include "view_direction_classification/estimation/refined_measurement.h"

#include <cmath>
#include <string>
#include <vector>

#include "view_direction_classification/common/error.h"

namespace vdc {

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
    const Eigen::Vector4d& q = pose.orientation;
    components.push_back(
        BinghamDistribution::fromExponentMatrix(parameters.concentration * q * q.transpose()));
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
