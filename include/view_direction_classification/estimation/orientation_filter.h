#pragma once

#include "view_direction_classification/bingham/bingham_mixture.h"

#include <Eigen/Core>

#include <cstdint>

namespace vdc {

struct OrientationFilterOptions {
  MixtureReductionOptions reduction;
  MapOptions map;
  // Products of a component with one far sharper than it keep the sharper one's shape and mode
  // (multiplyKeepingSharpFactor, bingham.h); 0: every product exact.
  double sharpness_ratio = 0.0;
  // Monte Carlo entropy of a multi-component belief (BinghamMixture::entropy).
  int entropy_samples = 4000;
  std::uint64_t entropy_seed = 1;
};

// The sequential Bayesian filter over the orientation q_WO of a static object in the fixed frame
// (doc/method.md section 9): the prior is uniform (F = 2 pi^2), each measurement (a view's mixture,
// already moved into the fixed frame) multiplies the belief with exact Bayesian weights and the
// result is reduced. The camera may move between updates; the object must not.
class OrientationFilter {
 public:
  // Throws vdc::Error for invalid options.
  explicit OrientationFilter(OrientationFilterOptions options = {});

  // belief <- reduce(belief x measurement).
  void update(const BinghamMixture& measurement);
  // Back to the uniform prior.
  void reset();
  // New options (throws vdc::Error for invalid ones, keeping the old): the belief is kept and
  // the next update() reduces with them.
  void setOptions(OrientationFilterOptions options);
  // A belief saved earlier and its update count (a restart); throws vdc::Error for a negative
  // count, keeping the old belief.
  void restore(BinghamMixture belief, int update_count);

  const BinghamMixture& belief() const { return belief_; }
  int updateCount() const { return update_count_; }
  // The MAP orientation q_WO of the current belief (w >= 0).
  Eigen::Vector4d mapEstimate() const;
  // The belief's entropy in nats: exact for one component, a fixed-seed Monte Carlo estimate for
  // a mixture (see BinghamMixture::entropy); log(2 pi^2) = 2.98 for the prior.
  double entropy() const;

 private:
  OrientationFilterOptions options_;
  BinghamMixture belief_;
  int update_count_ = 0;
};

}  // namespace vdc
