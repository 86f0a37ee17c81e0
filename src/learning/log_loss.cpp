#include "view_direction_classification/learning/log_loss.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "view_direction_classification/common/error.h"

namespace vdc {

double flooredNegativeLog(double p) { return -std::log(std::max(p, kKlProbabilityFloor)); }

Eigen::VectorXf featureKlDivergences(const Eigen::MatrixXf& probabilities,
                                     const Eigen::VectorXi& labels) {
  if (labels.size() != probabilities.rows()) {
    throw Error("surface informativeness: " + std::to_string(probabilities.rows()) +
                " feature distributions but " + std::to_string(labels.size()) + " labels");
  }
  Eigen::VectorXf kl(labels.size());
  for (Eigen::Index i = 0; i < labels.size(); ++i) {
    if (labels(i) < 0 || labels(i) >= probabilities.cols()) {
      throw Error("surface informativeness: label " + std::to_string(labels(i)) + " of feature " +
                  std::to_string(i) + " is outside [0, " + std::to_string(probabilities.cols()) +
                  ")");
    }
    const double p = probabilities(i, labels(i));
    if (!std::isfinite(p) || p < 0.0) {
      throw Error("surface informativeness: feature " + std::to_string(i) +
                  " has an invalid probability " + std::to_string(p));
    }
    kl(i) = static_cast<float>(flooredNegativeLog(p));
  }
  return kl;
}

}  // namespace vdc
