#include "view_direction_classification/bingham/bingham.h"

#include "view_direction_classification/bingham/bingham_normalizer.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/quaternion.h"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <sstream>
#include <string>

namespace vdc {
namespace {

constexpr double kOrthonormalTolerance = 1e-6;

// Gives a direction a deterministic sign (largest-magnitude component positive), so that equal
// distributions have equal printed axes and modes.
Eigen::Vector4d canonicalSign(const Eigen::Vector4d& v) {
  Eigen::Index largest = 0;
  v.cwiseAbs().maxCoeff(&largest);
  return v(largest) < 0.0 ? Eigen::Vector4d(-v) : v;
}

}  // namespace

BinghamDistribution::BinghamDistribution() {
  initialise(Eigen::Vector3d::Zero(), Eigen::Matrix4d::Identity().rowwise().reverse());
}

BinghamDistribution::BinghamDistribution(const Eigen::Vector3d& concentrations, const Axes& axes) {
  if (!concentrations.allFinite() || (concentrations.array() > 0.0).any()) {
    std::ostringstream message;
    message << "Bingham concentrations must be finite and <= 0, but got ("
            << concentrations.transpose() << ").";
    throw Error(message.str());
  }
  if (!axes.allFinite() ||
      !(axes.transpose() * axes).isApprox(Eigen::Matrix3d::Identity(), kOrthonormalTolerance)) {
    std::ostringstream message;
    message << "Bingham axes must be finite and orthonormal, but their Gram matrix is\n"
            << axes.transpose() * axes << ".";
    throw Error(message.str());
  }
  // The mode: the direction orthogonal to the three axes (last column of a full QR basis).
  Eigen::HouseholderQR<Axes> qr(axes);
  const Eigen::Matrix4d q = qr.householderQ() * Eigen::Matrix4d::Identity();
  Eigen::Matrix4d basis;
  basis.leftCols<3>() = axes;
  basis.col(3) = q.col(3).normalized();
  initialise(concentrations, basis);
}

void BinghamDistribution::initialise(const Eigen::Vector3d& concentrations,
                                     const Eigen::Matrix4d& basis) {
  std::array<int, 3> order{0, 1, 2};
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return concentrations(a) < concentrations(b); });
  for (int i = 0; i < 3; ++i) {
    concentrations_(i) = concentrations(order[i]);
    basis_.col(i) = canonicalSign(basis.col(order[i]));
  }
  basis_.col(3) = canonicalSign(basis.col(3));
  exponent_ =
      basis_.leftCols<3>() * concentrations_.asDiagonal() * basis_.leftCols<3>().transpose();
  normalizer_ = binghamNormalizer(concentrations_);
  log_normalizer_ = std::log(normalizer_);
}

BinghamDistribution BinghamDistribution::fromExponentMatrix(const Eigen::Matrix4d& exponent,
                                                            double* log_scale) {
  if (!exponent.allFinite()) {
    throw Error("The exponent matrix of a Bingham distribution must be finite.");
  }
  const Eigen::Matrix4d symmetric = 0.5 * (exponent + exponent.transpose());
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix4d> solver(symmetric);
  const Eigen::Vector4d eigenvalues = solver.eigenvalues();  // ascending
  const double largest = eigenvalues(3);
  BinghamDistribution result;
  // Differences to the largest eigenvalue are <= 0 by construction; min() guards the rounding.
  const Eigen::Vector3d concentrations = (eigenvalues.head<3>().array() - largest).min(0.0);
  result.initialise(concentrations, solver.eigenvectors());
  if (log_scale != nullptr) *log_scale = largest;
  return result;
}

Eigen::Vector4d BinghamDistribution::axis(int i) const {
  if (i < 0 || i > 2) {
    throw Error("A Bingham distribution has axes 0, 1 and 2 only, but axis " + std::to_string(i) +
                " was requested.");
  }
  return basis_.col(i);
}

Eigen::Vector3d BinghamDistribution::normalizerGradient() const {
  return binghamNormalizerWithGradient(concentrations_).gradient;
}

Eigen::Vector3d BinghamDistribution::axisMoments() const {
  const BinghamNormalizer f = binghamNormalizerWithGradient(concentrations_);
  return f.gradient / f.value;
}

Eigen::Matrix4d BinghamDistribution::scatterMatrix() const {
  const Eigen::Vector3d moments = axisMoments();
  Eigen::Vector4d diagonal;
  diagonal << moments, std::max(0.0, 1.0 - moments.sum());
  return basis_ * diagonal.asDiagonal() * basis_.transpose();
}

double BinghamDistribution::entropy() const {
  return log_normalizer_ - concentrations_.dot(axisMoments());
}

double BinghamDistribution::logDensity(const Eigen::Vector4d& x) const {
  checkUnitQuaternion(x, "at which a Bingham density is evaluated");
  return logDensityUnchecked(x);
}

double BinghamDistribution::density(const Eigen::Vector4d& x) const {
  return std::exp(logDensity(x));
}

BinghamDistribution BinghamDistribution::rotated(const Eigen::Vector4d& q) const {
  checkUnitQuaternion(q, "rotating a Bingham distribution");
  BinghamDistribution result = *this;
  const Eigen::Matrix4d rotation = quaternionLeftMatrix(q.normalized());
  result.basis_ = rotation * basis_;
  for (int i = 0; i < 4; ++i) result.basis_.col(i) = canonicalSign(result.basis_.col(i));
  result.exponent_ = rotation * exponent_ * rotation.transpose();
  return result;
}

double klDivergence(const BinghamDistribution& p, const BinghamDistribution& q) {
  // E_p[log p] = -H(p); E_p[log q] = tr(A_q E_p[x x^T]) - log F_q.
  const double cross = (q.exponentMatrix() * p.scatterMatrix()).trace() - q.logNormalizer();
  return std::max(0.0, -p.entropy() - cross);
}

BinghamProduct multiply(const BinghamDistribution& first, const BinghamDistribution& second) {
  BinghamProduct product;
  double largest_eigenvalue = 0.0;
  product.distribution = BinghamDistribution::fromExponentMatrix(
      first.exponentMatrix() + second.exponentMatrix(), &largest_eigenvalue);
  product.log_scale = largest_eigenvalue + product.distribution.logNormalizer() -
                      first.logNormalizer() - second.logNormalizer();
  return product;
}

namespace {

// Whether `sharp` is at least `ratio` times more concentrated along each axis than `wide` along
// its tightest one (concentrations are sorted ascending: z1 the tightest, z3 the loosest).
bool farSharper(const BinghamDistribution& sharp, const BinghamDistribution& wide, double ratio) {
  const double loosest = -sharp.concentrations()(2);
  return loosest > 0.0 && loosest >= ratio * -wide.concentrations()(0);
}

}  // namespace

void checkSharpnessRatio(double sharpness_ratio) {
  if (!std::isfinite(sharpness_ratio) || !(sharpness_ratio == 0.0 || sharpness_ratio >= 1.0)) {
    throw Error("a product's sharpness ratio must be 0 (exact) or at least 1, got " +
                std::to_string(sharpness_ratio));
  }
}

BinghamProduct multiplyKeepingSharpFactor(const BinghamDistribution& first,
                                          const BinghamDistribution& second,
                                          double sharpness_ratio) {
  checkSharpnessRatio(sharpness_ratio);
  if (sharpness_ratio == 0.0) return multiply(first, second);
  const BinghamDistribution* sharp = nullptr;
  const BinghamDistribution* wide = nullptr;
  if (farSharper(first, second, sharpness_ratio)) {
    sharp = &first;
    wide = &second;
  } else if (farSharper(second, first, sharpness_ratio)) {
    sharp = &second;
    wide = &first;
  } else {
    return multiply(first, second);
  }
  BinghamProduct product;
  product.distribution = *sharp;
  product.log_scale = wide->logDensity(sharp->mode());
  return product;
}

}  // namespace vdc
