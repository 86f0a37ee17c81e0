#pragma once

#include <Eigen/Core>

#include <cstdint>

#include "view_direction_classification/bingham/bingham_mixture.h"

namespace vdc {

// How far a belief spreads around its MAP orientation, from one set of fixed-seed samples, so
// that the published cone and covariance agree (doc/method.md section 12).
struct BeliefSpread {
  // Geodesic radius [rad] around the MAP that holds 50 % and 90 % of the belief's mass (the
  // samples' rotation angles away from the MAP, 2 arccos |<q, q_MAP>|, at those quantiles).
  double cone50 = M_PI, cone90 = M_PI;
  // 3 x 3 second moment [rad^2] of the samples' world-frame rotation vectors log(q (x) q_MAP^-1):
  // the orientation covariance of a ROS pose.
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Identity();
};

// Throws vdc::Error for samples < 10 or a non-unit map.
BeliefSpread beliefSpread(const BinghamMixture& belief, const Eigen::Vector4d& map,
                          int samples = 1000, std::uint64_t seed = 7);

}  // namespace vdc
