#pragma once

#include "view_direction_classification/bingham/bingham.h"

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace vdc {

// Concentrations of fitted distributions are bounded by this magnitude: a scatter matrix of
// rank < 4 (one sample, or identical ones) would otherwise ask for an infinite concentration.
// 1e6 is a width of about 0.06 degrees, far below any sensor's resolution.
constexpr double kMaxFittedConcentration = 1e6;

// Maximum-likelihood Bingham distribution for a scatter matrix S = E[x x^T] (symmetric,
// positive semi-definite; scaled to unit trace here). The axes are the eigenvectors of S; the
// concentrations solve E_z[(v_i . x)^2] = s_i (the moment equations of the likelihood), found by
// a quasi-Newton (BFGS) ascent on the concave log-likelihood sum_i z_i s_i - log F(z). Throws
// vdc::Error for a non-finite, non-symmetric, indefinite or zero matrix. `initial_concentrations`
// (<= 0, any order), when given, start the ascent instead of the asymptotic guess: a mixture
// reduction merging near-identical components passes the heaviest one's and converges in a step
// or two. The result is the same to the solver's 1e-9 tolerance either way.
BinghamDistribution fitBinghamToScatter(
    const Eigen::Matrix4d& scatter,
    const std::optional<Eigen::Vector3d>& initial_concentrations = std::nullopt);

// The weighted scatter matrix sum_k w_k x_k x_k^T / sum_k w_k of unit quaternions (signs do not
// matter). Empty weights mean equal weights. Throws vdc::Error for no samples, non-unit or
// non-finite samples, negative or non-finite weights, a weight count that differs from the
// sample count, or weights summing to zero.
Eigen::Matrix4d weightedScatterMatrix(const std::vector<Eigen::Vector4d>& samples,
                                      const std::vector<double>& weights = {});

// fitBinghamToScatter(weightedScatterMatrix(samples, weights)).
BinghamDistribution fitBingham(const std::vector<Eigen::Vector4d>& samples,
                               const std::vector<double>& weights = {});

}  // namespace vdc
