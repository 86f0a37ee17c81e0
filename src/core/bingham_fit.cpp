#include "view_direction_classification/core/bingham_fit.h"

#include "view_direction_classification/core/bingham_normalizer.h"
#include "view_direction_classification/core/error.h"
#include "view_direction_classification/core/quaternion.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

namespace vdc {
namespace {

// Moments E[x_i^2] of the axis-aligned Bingham distribution with concentrations z.
Eigen::Vector3d axisMoments(const Eigen::Vector3d& z) {
  const BinghamNormalizer f = binghamNormalizerWithGradient(z);
  return f.gradient / f.value;
}

// Solves E_z[x_i^2] = s_i for z <= 0 by projected Newton ascent on the concave log-likelihood
// L(z) = z . s - log F(z), whose Hessian is minus the covariance of (x_1^2, x_2^2, x_3^2); that
// Hessian is taken by finite differences of the exact gradient.
Eigen::Vector3d solveMomentEquations(const Eigen::Vector3d& s,
                                     const std::optional<Eigen::Vector3d>& initial) {
  const auto log_likelihood = [&](const Eigen::Vector3d& z) {
    return z.dot(s) - std::log(binghamNormalizer(z));
  };
  // Start from the asymptotic relations: E[x_i^2] ~ -1/(2 z_i) when concentrated, and z = 0 at
  // the uniform moments 1/4.
  Eigen::Vector3d z;
  for (int i = 0; i < 3; ++i) z(i) = std::min(0.0, 2.0 - 1.0 / (2.0 * s(i)));
  double value = log_likelihood(z);
  if (initial && initial->allFinite()) {
    // Both sorted ascending: the smallest moment pairs with the most negative concentration.
    Eigen::Vector3d guess = initial->cwiseMin(0.0).cwiseMax(-kMaxFittedConcentration);
    std::sort(guess.data(), guess.data() + 3);
    std::array<int, 3> order{0, 1, 2};
    std::sort(order.begin(), order.end(), [&](int a, int b) { return s(a) < s(b); });
    Eigen::Vector3d start;
    for (int i = 0; i < 3; ++i) start(order[i]) = guess(i);
    const double start_value = log_likelihood(start);
    if (start_value > value) z = start, value = start_value;
  }
  for (int iteration = 0; iteration < 200; ++iteration) {
    const Eigen::Vector3d moments = axisMoments(z);
    const Eigen::Vector3d gradient = s - moments;
    // Converged when every moment equation holds to 1e-9 relative, or the only violations sit
    // on the boundary z_i = 0 pushing outwards (moment larger than the uniform one's reach).
    bool converged = true;
    for (int i = 0; i < 3; ++i) {
      const bool pinned = z(i) == 0.0 && gradient(i) > 0.0;
      if (!pinned && std::abs(gradient(i)) > 1e-9 * s(i)) converged = false;
    }
    if (converged) break;

    Eigen::Matrix3d hessian;  // d moments / d z = -Hessian of L
    for (int j = 0; j < 3; ++j) {
      const double h = 1e-6 * std::max(1.0, std::abs(z(j)));
      Eigen::Vector3d shifted = z;
      shifted(j) -= h;  // step inwards so z stays <= 0
      hessian.col(j) = (moments - axisMoments(shifted)) / h;
    }
    hessian = 0.5 * (hessian + hessian.transpose()).eval();
    Eigen::Vector3d step = hessian.ldlt().solve(gradient);
    if (!step.allFinite() || step.dot(gradient) <= 0.0) step = gradient;  // fall back to ascent
    // Backtracking line search on L, projecting onto z <= 0.
    double scale = 1.0;
    bool improved = false;
    for (int trial = 0; trial < 60; ++trial, scale *= 0.5) {
      Eigen::Vector3d candidate = (z + scale * step).cwiseMin(0.0);
      candidate = candidate.cwiseMax(-kMaxFittedConcentration);
      const double candidate_value = log_likelihood(candidate);
      if (candidate_value >= value) {
        z = candidate;
        value = candidate_value;
        improved = true;
        break;
      }
    }
    if (!improved) break;  // at the optimum to machine precision
  }
  return z;
}

}  // namespace

BinghamDistribution fitBinghamToScatter(const Eigen::Matrix4d& scatter,
                                        const std::optional<Eigen::Vector3d>& initial) {
  if (!scatter.allFinite()) throw Error("A scatter matrix to fit a Bingham to must be finite.");
  const double scale = scatter.cwiseAbs().maxCoeff();
  if (scale == 0.0 || (scatter - scatter.transpose()).cwiseAbs().maxCoeff() > 1e-9 * scale) {
    throw Error("A scatter matrix to fit a Bingham to must be symmetric and non-zero.");
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> solver(scatter);
  Eigen::Vector4d eigenvalues = solver.eigenvalues();  // ascending
  if (eigenvalues(0) < -1e-9 * scale) {
    std::ostringstream message;
    message << "A scatter matrix to fit a Bingham to must be positive semi-definite, but has "
               "eigenvalue "
            << eigenvalues(0) << ".";
    throw Error(message.str());
  }
  eigenvalues /= eigenvalues.sum();
  // Moments below the floor would need concentrations beyond kMaxFittedConcentration.
  const double floor = 1.0 / (2.0 * kMaxFittedConcentration);
  const Eigen::Vector3d moments = eigenvalues.head<3>().cwiseMax(floor);
  const Eigen::Vector3d concentrations = solveMomentEquations(moments, initial);
  return BinghamDistribution(concentrations, solver.eigenvectors().leftCols<3>());
}

Eigen::Matrix4d weightedScatterMatrix(const std::vector<Eigen::Vector4d>& samples,
                                      const std::vector<double>& weights) {
  if (samples.empty()) throw Error("Fitting a Bingham distribution needs at least one sample.");
  if (!weights.empty() && weights.size() != samples.size()) {
    std::ostringstream message;
    message << "Fitting a Bingham distribution got " << samples.size() << " samples but "
            << weights.size() << " weights.";
    throw Error(message.str());
  }
  Eigen::Matrix4d scatter = Eigen::Matrix4d::Zero();
  double total = 0.0;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    checkUnitQuaternion(samples[k], "of a sample to fit a Bingham to");
    const double w = weights.empty() ? 1.0 : weights[k];
    if (!std::isfinite(w) || w < 0.0) {
      std::ostringstream message;
      message << "Sample weights for a Bingham fit must be finite and >= 0, but weight " << k
              << " is " << w << ".";
      throw Error(message.str());
    }
    scatter += w * samples[k] * samples[k].transpose();
    total += w;
  }
  if (total <= 0.0) throw Error("The sample weights for a Bingham fit sum to zero.");
  return scatter / total;
}

BinghamDistribution fitBingham(const std::vector<Eigen::Vector4d>& samples,
                               const std::vector<double>& weights) {
  return fitBinghamToScatter(weightedScatterMatrix(samples, weights));
}

}  // namespace vdc
