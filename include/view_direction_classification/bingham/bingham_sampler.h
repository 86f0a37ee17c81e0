#pragma once

#include "view_direction_classification/bingham/bingham.h"

#include <Eigen/Core>

#include <random>
#include <vector>

namespace vdc {

// Exact sampling from a Bingham distribution by rejection from an angular central Gaussian
// envelope (Kent, Ganeiber & Mardia 2013): propose y ~ N(0, Omega^-1) in the distribution's
// basis with Omega = I + 2 Lambda / b, x = y / |y|, and accept with probability
//   exp(-x^T Lambda x) (x^T Omega x)^2 / M,   M = e^{-(4-b)/2} (4/b)^2,
// where Lambda = diag(-z, 0) and b solves sum_i 1 / (b + 2 lambda_i) = 1, the choice that
// minimises M. The acceptance rate is at least 1/M >= 28 % for every concentration, and the
// samples are independent (unlike Metropolis-Hastings chains).
class BinghamSampler {
 public:
  explicit BinghamSampler(const BinghamDistribution& distribution);

  // One sample (a unit quaternion, sign arbitrary). Deterministic for a seeded generator.
  Eigen::Vector4d operator()(std::mt19937_64& generator) const;
  std::vector<Eigen::Vector4d> sample(int count, std::mt19937_64& generator) const;

  // The envelope bound M (expected proposals per sample).
  double envelopeBound() const { return std::exp(log_bound_); }

 private:
  Eigen::Matrix4d basis_;
  Eigen::Vector4d lambda_;            // -z and 0 for the mode
  Eigen::Vector4d proposal_std_dev_;  // 1 / sqrt(Omega_ii)
  double b_ = 4.0;
  double log_bound_ = 0.0;
};

}  // namespace vdc
