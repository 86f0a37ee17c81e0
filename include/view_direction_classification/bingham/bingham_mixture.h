#pragma once

#include "view_direction_classification/bingham/bingham.h"

#include <Eigen/Core>

#include <cstdint>
#include <random>
#include <vector>

namespace vdc {

// A finite mixture sum_k w_k B_k(x) of Bingham distributions on S^3 with weights summing to 1.
// It is never empty: the default is the uniform distribution, and constructing one from no
// components throws.
class BinghamMixture {
 public:
  // The uniform distribution on S^3 (one component, F = 2 pi^2): the filter's prior.
  BinghamMixture();

  // Weights are normalised here. Throws vdc::Error for no components, a count mismatch, or
  // weights that are negative, non-finite or sum to zero.
  BinghamMixture(std::vector<double> weights, std::vector<BinghamDistribution> components);

  // Builds from unnormalised log weights (so products of tiny numbers never underflow).
  // Throws vdc::Error as the constructor, or for a NaN or +inf log weight or all -inf.
  static BinghamMixture fromLogWeights(const std::vector<double>& log_weights,
                                       std::vector<BinghamDistribution> components);

  std::size_t size() const { return components_.size(); }
  const std::vector<double>& weights() const { return weights_; }
  const std::vector<BinghamDistribution>& components() const { return components_; }
  double weight(std::size_t k) const { return weights_.at(k); }
  const BinghamDistribution& component(std::size_t k) const { return components_.at(k); }

  // Density at a unit quaternion (log-sum-exp inside). Throws vdc::Error for non-unit x.
  double density(const Eigen::Vector4d& x) const;
  double logDensity(const Eigen::Vector4d& x) const;

  // Independent samples (component by weight, then the exact Bingham sampler).
  std::vector<Eigen::Vector4d> sample(int count, std::mt19937_64& generator) const;

  // Differential entropy in nats. Exact for one component. A mixture's entropy has no closed
  // form: this is the Monte Carlo estimate -mean log p(x_s) over `samples` draws from the mixture
  // with a fixed seed (so repeated calls agree); its standard error is about sd(log p)/sqrt(n).
  double entropy(int samples = 4000, std::uint64_t seed = 1) const;

  // Every component rotated by q (left multiplication): q (x) x ~ the result when x ~ this.
  BinghamMixture rotated(const Eigen::Vector4d& q) const;

 private:
  std::vector<double> weights_;
  std::vector<BinghamDistribution> components_;
};

// The normalised product a(x) b(x) / integral(a b): component (i, j) is the product B_i B_j with
// the exact Bayesian weight w_ij ~ w_i w_j e^{lambda_max,ij} F(Z_ij) / (F_i F_j), i.e. w_i w_j
// times the overlap integral of B_i and B_j, computed in log space.
//
// With relative_weight_floor > 0, components lighter than that fraction of the heaviest are left
// out (what reduce() would drop anyway): a pair's weight is bounded from above with F(Z_ij) <=
// 2 pi^2 from one 4 x 4 eigen-decomposition, and the normaliser - the expensive part - is only
// computed for pairs whose bound clears the floor. Pairs are computed in parallel (OpenMP); the
// result does not depend on the thread count.
//
// With sharpness_ratio > 0, a pair whose one factor is far sharper than the other is the sharper
// factor weighted by the other's density at its mode (multiplyKeepingSharpFactor, bingham.h).
// Throws vdc::Error for a floor outside [0, 1) or an invalid sharpness ratio.
BinghamMixture multiply(const BinghamMixture& a, const BinghamMixture& b,
                        double relative_weight_floor = 0.0, double sharpness_ratio = 0.0);

struct MixtureReductionOptions {
  // Components lighter than this fraction of the heaviest one are dropped.
  double relative_weight_threshold = 1e-6;
  // Components are merged (moment matching of their scatter matrices, then an ML refit) when
  // their modes are within this rotation angle [rad] ...
  double merge_angle = 5.0 * M_PI / 180.0;
  // ... and each resembles the other near its mode: at the mode and one standard deviation
  // either way along its loosest axis, the other's log density (relative to its peak) is at most
  // merge_log_density lower than its own. This keeps apart girdles (whose modes are arbitrary
  // points of their circles) that share a point but not their circle, and sharp components that
  // are distinct hypotheses despite close modes.
  double merge_log_density = 2.0;
  // At most this many components (the heaviest) are kept.
  int max_components = 200;
};

// Drops, merges and caps as the options say; the weights are renormalised. Throws vdc::Error for
// invalid options (negative threshold or angle, max_components < 1).
BinghamMixture reduce(const BinghamMixture& mixture, const MixtureReductionOptions& options = {});

struct MapOptions {
  // Extra starting points spread along the circle of components whose loosest concentration
  // is weaker than girdle_concentration (girdles: their mode is an arbitrary point of a circle).
  int girdle_start_points = 8;
  double girdle_concentration = 2.0;
  // The starting points with the highest density are refined (all when <= 0).
  int max_refined_starts = 32;
  int max_iterations = 500;
};

// The maximum of the mixture density (the MAP orientation, sign-normalised with w >= 0): every
// component's mode (and points along the circle for girdles) is a start; the best starts are
// refined by projected gradient ascent on log p over S^3 with a backtracking line search.
Eigen::Vector4d mapEstimate(const BinghamMixture& mixture, const MapOptions& options = {});

}  // namespace vdc
