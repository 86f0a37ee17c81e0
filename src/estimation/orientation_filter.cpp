#include "view_direction_classification/estimation/orientation_filter.h"

#include <string>
#include <utility>

#include "view_direction_classification/common/error.h"

namespace vdc {

OrientationFilter::OrientationFilter(OrientationFilterOptions options) {
  setOptions(std::move(options));
}

void OrientationFilter::setOptions(OrientationFilterOptions options) {
  if (options.entropy_samples < 1) {
    throw Error("The orientation filter's entropy_samples must be at least 1.");
  }
  // Validates the reduction options now rather than at the next update (the result is not
  // kept: the belief is only reduced by update()).
  reduce(BinghamMixture(), options.reduction);
  checkSharpnessRatio(options.sharpness_ratio);
  options_ = std::move(options);
}

void OrientationFilter::update(const BinghamMixture& measurement) {
  // Products that reduce() would drop are never computed (the normalisers dominate the cost).
  belief_ = reduce(multiply(belief_, measurement, options_.reduction.relative_weight_threshold,
                            options_.sharpness_ratio),
                   options_.reduction);
  ++update_count_;
}

void OrientationFilter::restore(BinghamMixture belief, int update_count) {
  if (update_count < 0) {
    throw Error("The orientation filter's update count must be >= 0, got " +
                std::to_string(update_count) + ".");
  }
  belief_ = std::move(belief);
  update_count_ = update_count;
}

void OrientationFilter::reset() {
  belief_ = BinghamMixture();
  update_count_ = 0;
}

Eigen::Vector4d OrientationFilter::mapEstimate() const {
  return vdc::mapEstimate(belief_, options_.map);
}

double OrientationFilter::entropy() const {
  return belief_.entropy(options_.entropy_samples, options_.entropy_seed);
}

}  // namespace vdc
