#pragma once

#include <Eigen/Core>

namespace vdc {

// A Bingham distribution on the unit quaternions S^3 (antipodally symmetric, so q and -q, the
// same rotation, have the same density):
//   p(x) = exp(sum_i z_i (v_i . x)^2) / F(z),   z1 <= z2 <= z3 <= 0,
// with orthonormal axes v1, v2, v3 in R^4; the fourth orthonormal direction, the mode, has
// concentration 0 and is where the density peaks. Quaternions are (w, x, y, z).
//
// The value type is immutable: it is built valid (validated concentrations and axes, sorted, F
// computed once) and every operation returns a new one.
class BinghamDistribution {
 public:
  using Axes = Eigen::Matrix<double, 4, 3>;

  // The uniform distribution (z = 0, F = 2 pi^2); its axes and mode are the identity basis.
  BinghamDistribution();

  // Concentrations (any order; sorted ascending here, the axes permuted with them) and the
  // matching axes as columns. Throws vdc::Error for non-finite or positive concentrations or
  // axes that are not orthonormal (tolerance 1e-6).
  BinghamDistribution(const Eigen::Vector3d& concentrations, const Axes& axes);

  // The distribution proportional to exp(x^T A x) for a symmetric A: the eigenvectors of A are
  // the axes, its eigenvalues shifted by the largest one, lambda_max, the concentrations (on S^3
  // x^T x = 1, so the shift only rescales). If log_scale is given it receives lambda_max, i.e.
  // exp(x^T A x) = exp(lambda_max) F(z) p(x). Throws vdc::Error for a non-finite A.
  static BinghamDistribution fromExponentMatrix(const Eigen::Matrix4d& exponent,
                                                double* log_scale = nullptr);

  // Accessors for consumers (e.g. the ROS message: concentrations, axes and mode as quaternions,
  // normaliser).
  const Eigen::Vector3d& concentrations() const { return concentrations_; }
  Axes axes() const { return basis_.leftCols<3>(); }
  Eigen::Vector4d axis(int i) const;  // i in {0, 1, 2}
  // The mode, sign-normalised so that its largest-magnitude component is positive.
  Eigen::Vector4d mode() const { return basis_.col(3); }
  // Orthogonal 4x4 matrix with columns v1, v2, v3, mode.
  const Eigen::Matrix4d& basis() const { return basis_; }
  double normalizer() const { return normalizer_; }
  double logNormalizer() const { return log_normalizer_; }
  // sum_i z_i v_i v_i^T: the density is exp(x^T A x) / F.
  const Eigen::Matrix4d& exponentMatrix() const { return exponent_; }

  // dF/dz_i (one quadrature per call).
  Eigen::Vector3d normalizerGradient() const;
  // E[(v_i . x)^2] = (dF/dz_i) / F.
  Eigen::Vector3d axisMoments() const;
  // The second moment E[x x^T] = sum_i E[(v_i.x)^2] v_i v_i^T + (1 - sum) mode mode^T.
  Eigen::Matrix4d scatterMatrix() const;
  // Differential entropy in nats with respect to the surface measure of S^3:
  // log F - sum_i z_i E[(v_i . x)^2]. The uniform distribution has log(2 pi^2).
  double entropy() const;

  // Density at a unit quaternion x. Throws vdc::Error for a non-finite or non-unit x.
  double density(const Eigen::Vector4d& x) const;
  double logDensity(const Eigen::Vector4d& x) const;
  // log density without the input check, for inner loops whose x is known to be unit.
  double logDensityUnchecked(const Eigen::Vector4d& x) const {
    return x.dot(exponent_ * x) - log_normalizer_;
  }

  // The distribution of q (x) x when x follows this one: every axis left-multiplied by q. This is
  // how a belief about q_CO becomes one about q_WO = q_WC (x) q_CO.
  BinghamDistribution rotated(const Eigen::Vector4d& q) const;

 private:
  void initialise(const Eigen::Vector3d& concentrations, const Eigen::Matrix4d& basis);

  Eigen::Vector3d concentrations_;
  Eigen::Matrix4d basis_;
  Eigen::Matrix4d exponent_;
  double normalizer_ = 0.0;
  double log_normalizer_ = 0.0;
};

// KL(p || q) = E_p[log p(x) - log q(x)] >= 0, exact (closed form in the moments of p).
double klDivergence(const BinghamDistribution& p, const BinghamDistribution& q);

// The product p1(x) p2(x) = exp(log_scale) p12(x) with p12 a Bingham distribution, so
// exp(log_scale) = integral of p1 p2 over S^3 = e^{lambda_max} F(z12) / (F1 F2). Kept as a log:
// for concentrated factors it underflows.
struct BinghamProduct {
  BinghamDistribution distribution;
  double log_scale = 0.0;
};
BinghamProduct multiply(const BinghamDistribution& first, const BinghamDistribution& second);

// The product where one factor is far sharper than the other: when the sharper one is at least
// `sharpness_ratio` times more concentrated along its loosest axis than the other along its
// tightest (|z3| >= ratio |z1'|, z3 < 0), the product is the sharper factor itself, scaled by the
// other's density at its mode (Laplace's approximation of the overlap integral, exact when the
// other is uniform). Otherwise, or with ratio 0, the exact product above. Used where the wide
// factor's gradient across the sharp one is a model's artefact, not evidence: a coarse
// viewing-direction girdle would otherwise shift a geometric fit's mode by a fraction of a
// degree. Throws vdc::Error for a ratio that is negative, in (0, 1) or not finite.
BinghamProduct multiplyKeepingSharpFactor(const BinghamDistribution& first,
                                          const BinghamDistribution& second,
                                          double sharpness_ratio);
// The check multiplyKeepingSharpFactor makes of its ratio (throws vdc::Error).
void checkSharpnessRatio(double sharpness_ratio);

}  // namespace vdc
