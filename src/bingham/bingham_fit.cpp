#include "view_direction_classification/bingham/bingham_fit.h"

#include "view_direction_classification/bingham/bingham_normalizer.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/quaternion.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <sstream>

namespace vdc {
namespace {

// The log-likelihood L(z) = z . s - log F(z) and its gradient s - E_z[x_i^2], from one
// normaliser evaluation.
struct LikelihoodPoint {
  Eigen::Vector3d z;
  Eigen::Vector3d moments;  // E_z[x_i^2]
  double value;

  LikelihoodPoint(const Eigen::Vector3d& at, const Eigen::Vector3d& s) : z(at) {
    const BinghamNormalizer f = binghamNormalizerWithGradient(z);
    moments = f.gradient / f.value;
    value = z.dot(s) - std::log(f.value);
  }
  Eigen::Vector3d gradient(const Eigen::Vector3d& s) const { return s - moments; }
};

double logLikelihood(const Eigen::Vector3d& z, const Eigen::Vector3d& s) {
  return z.dot(s) - std::log(binghamNormalizer(z));
}

Eigen::Vector3d projectToDomain(const Eigen::Vector3d& z) {
  return z.cwiseMin(0.0).cwiseMax(-kMaxFittedConcentration);
}

// d E_z[x_i^2] / d z_j (the covariance of the x_i^2, minus L's Hessian) by finite differences
// of the exact moments.
Eigen::Matrix3d momentJacobian(const LikelihoodPoint& at, const Eigen::Vector3d& s) {
  Eigen::Matrix3d jacobian;
  for (int j = 0; j < 3; ++j) {
    const double h = 1e-6 * std::max(1.0, std::abs(at.z(j)));
    Eigen::Vector3d shifted = at.z;
    shifted(j) -= h;  // step inwards so z stays <= 0
    jacobian.col(j) = (at.moments - LikelihoodPoint(shifted, s).moments) / h;
  }
  return 0.5 * (jacobian + jacobian.transpose());
}

// Solves E_z[x_i^2] = s_i for z <= 0 by projected quasi-Newton ascent on the concave
// log-likelihood L(z) = z . s - log F(z), whose Hessian is minus the covariance of
// (x_1^2, x_2^2, x_3^2). That covariance starts from its Gaussian approximation and is kept
// current by BFGS updates, so each step costs one normaliser with gradient instead of the four
// of a finite-difference Newton step (the fits dominate a mixture reduction).
Eigen::Vector3d solveMomentEquations(const Eigen::Vector3d& s,
                                     const std::optional<Eigen::Vector3d>& initial) {
  // Start from the asymptotic relations: E[x_i^2] ~ -1/(2 z_i) when concentrated, and z = 0 at
  // the uniform moments 1/4.
  Eigen::Vector3d z;
  for (int i = 0; i < 3; ++i) z(i) = std::min(0.0, 2.0 - 1.0 / (2.0 * s(i)));
  if (initial && initial->allFinite()) {
    // Both sorted ascending: the smallest moment pairs with the most negative concentration.
    Eigen::Vector3d guess = projectToDomain(*initial);
    std::sort(guess.data(), guess.data() + 3);
    std::array<int, 3> order{0, 1, 2};
    std::sort(order.begin(), order.end(), [&](int a, int b) { return s(a) < s(b); });
    Eigen::Vector3d start;
    for (int i = 0; i < 3; ++i) start(order[i]) = guess(i);
    if (logLikelihood(start, s) > logLikelihood(z, s)) z = start;
  }
  LikelihoodPoint current(z, s);
  // Where x is nearly Gaussian in the tangent space (concentrated), cov(x_i^2, x_j^2) = 2 m_i^2
  // delta_ij; near the uniform it is within a factor of two of that.
  Eigen::Matrix3d covariance = (2.0 * current.moments.array().square()).matrix().asDiagonal();
  for (int iteration = 0; iteration < 200; ++iteration) {
    const Eigen::Vector3d gradient = current.gradient(s);
    // Converged when every moment equation holds to 1e-9 relative, or the only violations sit
    // on the boundary z_i = 0 pushing outwards (moment larger than the uniform one's reach).
    bool converged = true;
    for (int i = 0; i < 3; ++i) {
      const bool pinned = current.z(i) == 0.0 && gradient(i) > 0.0;
      if (!pinned && std::abs(gradient(i)) > 1e-9 * s(i)) converged = false;
    }
    if (converged) break;

    Eigen::Vector3d step = covariance.ldlt().solve(gradient);
    if (!step.allFinite() || step.dot(gradient) <= 0.0) {
      covariance = momentJacobian(current, s);  // the quasi-Newton model went wrong: rebuild it
      step = covariance.ldlt().solve(gradient);
      if (!step.allFinite() || step.dot(gradient) <= 0.0) step = gradient;  // plain ascent
    }
    // The full step is kept when L rises, or when L's slope along the step is still >= 0 at its
    // end: L is concave, so it then rose along the whole step (a test that stays reliable where
    // the change in L drowns in the normaliser's rounding). Otherwise backtrack on L.
    std::optional<LikelihoodPoint> next;
    LikelihoodPoint candidate(projectToDomain(current.z + step), s);
    const Eigen::Vector3d moved = candidate.z - current.z;
    if (candidate.value >= current.value || candidate.gradient(s).dot(moved) >= 0.0) {
      next = candidate;
    } else {
      double scale = 0.5;
      for (int trial = 0; trial < 60; ++trial, scale *= 0.5) {
        const Eigen::Vector3d shorter = projectToDomain(current.z + scale * step);
        if (logLikelihood(shorter, s) >= current.value) {
          next = LikelihoodPoint(shorter, s);
          break;
        }
      }
    }
    if (!next || next->z == current.z) break;  // at the optimum to machine precision
    // BFGS update of the covariance model from the change in the moments along the step; the
    // true covariance is positive definite, so a step without positive curvature is noise.
    const Eigen::Vector3d dz = next->z - current.z;
    const Eigen::Vector3d dm = next->moments - current.moments;
    const double curvature = dz.dot(dm);
    const Eigen::Vector3d model = covariance * dz;
    if (curvature > 1e-12 * dz.norm() * dm.norm() && dz.dot(model) > 0.0) {
      covariance += dm * dm.transpose() / curvature - model * model.transpose() / dz.dot(model);
    }
    current = *next;
  }
  return current.z;
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
