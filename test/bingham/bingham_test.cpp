#include "view_direction_classification/bingham/bingham.h"
#include "support/random_unit_quaternions.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/quaternion.h"

#include <gtest/gtest.h>
#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <tuple>
#include <vector>

namespace vdc {
namespace {

constexpr double kTwoPiSquared = 2.0 * M_PI * M_PI;

// A random orthonormal basis of R^4 (fixed seed): columns 0..2 serve as axes.
Eigen::Matrix4d randomBasis(unsigned seed) {
  std::mt19937_64 generator(seed);
  std::normal_distribution<double> normal;
  Eigen::Matrix4d m;
  for (int i = 0; i < 16; ++i) m(i) = normal(generator);
  Eigen::HouseholderQR<Eigen::Matrix4d> qr(m);
  return qr.householderQ() * Eigen::Matrix4d::Identity();
}

BinghamDistribution makeDistribution(const Eigen::Vector3d& z, unsigned seed) {
  return BinghamDistribution(z, randomBasis(seed).leftCols<3>());
}

TEST(Bingham, DefaultIsUniform) {
  const BinghamDistribution uniform;
  EXPECT_NEAR(uniform.normalizer(), kTwoPiSquared, 1e-12);
  EXPECT_NEAR(uniform.entropy(), std::log(kTwoPiSquared), 1e-12);
  EXPECT_NEAR(uniform.density(Eigen::Vector4d(0.5, 0.5, 0.5, 0.5)), 1.0 / kTwoPiSquared, 1e-14);
  EXPECT_TRUE(uniform.scatterMatrix().isApprox(0.25 * Eigen::Matrix4d::Identity(), 1e-10));
}

TEST(Bingham, SortsConcentrationsWithTheirAxesAndCompletesTheMode) {
  const Eigen::Matrix4d basis = randomBasis(3);
  const BinghamDistribution b(Eigen::Vector3d(-1, -10, -5), basis.leftCols<3>());
  EXPECT_EQ(b.concentrations(), Eigen::Vector3d(-10, -5, -1));
  EXPECT_NEAR(std::abs(b.axis(0).dot(basis.col(1))), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(b.axis(2).dot(basis.col(0))), 1.0, 1e-12);
  EXPECT_NEAR(std::abs(b.mode().dot(basis.col(3))), 1.0, 1e-12);
  EXPECT_TRUE((b.basis().transpose() * b.basis()).isApprox(Eigen::Matrix4d::Identity(), 1e-12));
  // The density peaks at the mode.
  EXPECT_GT(b.logDensity(b.mode()), b.logDensity((b.mode() + 0.1 * b.axis(2)).normalized()));
}

TEST(Bingham, RejectsPositiveOrNonFiniteConcentrationsAndNonOrthonormalAxes) {
  const BinghamDistribution::Axes axes = randomBasis(1).leftCols<3>();
  EXPECT_THROW(BinghamDistribution(Eigen::Vector3d(-1, -1, 0.5), axes), Error);
  EXPECT_THROW(BinghamDistribution(Eigen::Vector3d(-1, NAN, 0), axes), Error);
  EXPECT_THROW(BinghamDistribution(Eigen::Vector3d(-1, -INFINITY, 0), axes), Error);
  BinghamDistribution::Axes scaled = axes;
  scaled.col(1) *= 1.01;
  EXPECT_THROW(BinghamDistribution(Eigen::Vector3d(-1, -1, 0), scaled), Error);
  BinghamDistribution::Axes nan_axes = axes;
  nan_axes(0, 0) = NAN;
  EXPECT_THROW(BinghamDistribution(Eigen::Vector3d(-1, -1, 0), nan_axes), Error);
  const BinghamDistribution b(Eigen::Vector3d(-1, -1, 0), axes);
  EXPECT_THROW(b.density(Eigen::Vector4d(1, 1, 0, 0)), Error);
  EXPECT_THROW(b.density(Eigen::Vector4d(NAN, 0, 0, 0)), Error);
  EXPECT_THROW(b.axis(3), Error);
}

TEST(Bingham, DensityIntegratesToOneAndScatterMatchesMonteCarlo) {
  const BinghamDistribution b = makeDistribution(Eigen::Vector3d(-6, -2, -0.5), 5);
  const std::vector<Eigen::Vector4d> points = test::randomUnitQuaternionsFromSeed(200000, 11);
  double mass = 0.0;
  Eigen::Matrix4d scatter = Eigen::Matrix4d::Zero();
  for (const Eigen::Vector4d& x : points) {
    const double weight = b.density(x) * kTwoPiSquared / points.size();
    mass += weight;
    scatter += weight * x * x.transpose();
  }
  EXPECT_NEAR(mass, 1.0, 0.01);
  EXPECT_LT((scatter - b.scatterMatrix()).cwiseAbs().maxCoeff(), 0.01);
  EXPECT_NEAR(b.scatterMatrix().trace(), 1.0, 1e-12);
}

TEST(Bingham, EntropyFallsWithConcentrationAndMatchesKlToUniform) {
  const BinghamDistribution broad = makeDistribution(Eigen::Vector3d(-1, -1, -1), 2);
  const BinghamDistribution sharp = makeDistribution(Eigen::Vector3d(-100, -100, -100), 2);
  EXPECT_LT(sharp.entropy(), broad.entropy());
  EXPECT_LT(broad.entropy(), std::log(kTwoPiSquared));
  const BinghamDistribution uniform;
  // KL(p || uniform) = log(2 pi^2) - H(p).
  EXPECT_NEAR(klDivergence(sharp, uniform), std::log(kTwoPiSquared) - sharp.entropy(), 1e-9);
  // For very large concentrations the distribution is a 3-D Gaussian of variance 1/(2k) per
  // axis (doubled: +-q), whose entropy is known in closed form.
  const double k = 1e5;
  const BinghamDistribution narrow = makeDistribution(Eigen::Vector3d(-k, -k, -k), 4);
  const double gaussian = 1.5 * std::log(2.0 * M_PI * M_E / (2.0 * k)) + std::log(2.0);
  EXPECT_NEAR(narrow.entropy(), gaussian, 1e-3);
}

TEST(Bingham, KlDivergenceIsZeroForItselfAndPositiveOtherwise) {
  const BinghamDistribution p = makeDistribution(Eigen::Vector3d(-20, -5, -1), 6);
  const BinghamDistribution q = makeDistribution(Eigen::Vector3d(-20, -5, -1), 7);
  EXPECT_NEAR(klDivergence(p, p), 0.0, 1e-9);
  EXPECT_GT(klDivergence(p, q), 0.1);
  // Against Monte Carlo: E_p[log p - log q] with importance weights from uniform samples.
  double kl = 0.0;
  const std::vector<Eigen::Vector4d> points = test::randomUnitQuaternionsFromSeed(200000, 12);
  for (const Eigen::Vector4d& x : points) {
    kl += p.density(x) * (p.logDensity(x) - q.logDensity(x)) * kTwoPiSquared / points.size();
  }
  EXPECT_NEAR(klDivergence(p, q), kl, 0.03 * kl);
}

TEST(Bingham, RotatedDensityAtRotatedPointEqualsOriginal) {
  const BinghamDistribution b = makeDistribution(Eigen::Vector3d(-30, -4, -1), 8);
  const Eigen::Vector4d q = quaternionFromAxisAngle(Eigen::Vector3d(1, 2, -1), 0.9);
  const BinghamDistribution r = b.rotated(q);
  for (const Eigen::Vector4d& x : test::randomUnitQuaternionsFromSeed(20, 13)) {
    EXPECT_NEAR(r.logDensity(quaternionMultiply(q, x)), b.logDensity(x), 1e-10);
  }
  EXPECT_NEAR(std::abs(r.mode().dot(quaternionMultiply(q, b.mode()))), 1.0, 1e-12);
  EXPECT_EQ(r.concentrations(), b.concentrations());
  EXPECT_THROW(b.rotated(Eigen::Vector4d(2, 0, 0, 0)), Error);
}

TEST(Bingham, ProductAddsExponentsAndItsScaleIsTheOverlapIntegral) {
  const BinghamDistribution a = makeDistribution(Eigen::Vector3d(-8, -3, -1), 9);
  const BinghamDistribution b = makeDistribution(Eigen::Vector3d(-5, -5, -0.2), 10);
  const BinghamProduct product = multiply(a, b);
  const std::vector<Eigen::Vector4d> points = test::randomUnitQuaternionsFromSeed(200000, 14);
  double overlap = 0.0;
  for (const Eigen::Vector4d& x : points) {
    overlap += a.density(x) * b.density(x) * kTwoPiSquared / points.size();
    if (&x - points.data() < 10) {  // pointwise identity p_a p_b = e^s p_ab
      EXPECT_NEAR(a.logDensity(x) + b.logDensity(x),
                  product.log_scale + product.distribution.logDensity(x), 1e-9);
    }
  }
  EXPECT_NEAR(std::exp(product.log_scale), overlap, 0.02 * overlap);
}

// A pose-like component (every concentration in the thousands) and a girdle (two tens, roll
// free) whose circle passes 20 degrees from the pose's mode.
struct SharpAndWide {
  BinghamDistribution sharp, wide;
};
SharpAndWide poseAndGirdle() {
  const Eigen::Matrix4d basis = randomBasis(21);
  SharpAndWide factors;
  factors.sharp = BinghamDistribution(Eigen::Vector3d(-3000, -2500, -2000), basis.leftCols<3>());
  // The girdle's circle: the pose's mode turned by 20 degrees towards its first axis.
  const double tilt = 20.0 * M_PI / 180.0;
  Eigen::Matrix4d girdle_basis = basis;
  girdle_basis.col(3) = std::cos(tilt) * basis.col(3) + std::sin(tilt) * basis.col(0);
  girdle_basis.col(0) = -std::sin(tilt) * basis.col(3) + std::cos(tilt) * basis.col(0);
  Eigen::Matrix<double, 4, 3> axes;
  axes << girdle_basis.col(0), girdle_basis.col(1), girdle_basis.col(2);
  factors.wide = BinghamDistribution(Eigen::Vector3d(-18, -18, 0), axes);
  return factors;
}

TEST(Bingham, AFarSharperFactorKeepsItsModeAndShapeWeightedByTheOtherAtItsMode) {
  const SharpAndWide f = poseAndGirdle();
  const BinghamProduct exact = multiply(f.sharp, f.wide);
  // The exact product's mode leans towards the girdle; the kept one does not.
  EXPECT_GT(std::acos(std::min(1.0, std::abs(exact.distribution.mode().dot(f.sharp.mode())))),
            1e-4);
  for (const bool sharp_first : {true, false}) {
    const BinghamProduct kept = sharp_first ? multiplyKeepingSharpFactor(f.sharp, f.wide, 10.0)
                                            : multiplyKeepingSharpFactor(f.wide, f.sharp, 10.0);
    EXPECT_NEAR(std::abs(kept.distribution.mode().dot(f.sharp.mode())), 1.0, 1e-12);
    EXPECT_EQ(kept.distribution.concentrations(), f.sharp.concentrations());
    EXPECT_NEAR(kept.log_scale, f.wide.logDensity(f.sharp.mode()), 1e-12);
    // Laplace's approximation of the overlap integral: close to the exact one.
    EXPECT_NEAR(kept.log_scale, exact.log_scale, 0.05);
  }
}

TEST(Bingham, FactorsOfComparableSharpnessMultiplyExactly) {
  const SharpAndWide f = poseAndGirdle();
  // 2000 against 18 is a ratio of 111: above it, or with ratio 0, the product is exact.
  const BinghamDistribution other = makeDistribution(Eigen::Vector3d(-900, -700, -500), 22);
  for (const auto& [first, second, ratio] :
       {std::make_tuple(f.sharp, f.wide, 200.0), std::make_tuple(f.sharp, f.wide, 0.0),
        std::make_tuple(f.sharp, other, 10.0)}) {
    const BinghamProduct exact = multiply(first, second);
    const BinghamProduct product = multiplyKeepingSharpFactor(first, second, ratio);
    EXPECT_TRUE(
        product.distribution.exponentMatrix().isApprox(exact.distribution.exponentMatrix(), 1e-12));
    EXPECT_DOUBLE_EQ(product.log_scale, exact.log_scale);
  }
}

TEST(Bingham, AUniformFactorKeepsTheOtherExactly) {
  const SharpAndWide f = poseAndGirdle();
  const BinghamProduct exact = multiply(f.sharp, BinghamDistribution());
  const BinghamProduct kept = multiplyKeepingSharpFactor(BinghamDistribution(), f.sharp, 10.0);
  EXPECT_NEAR(kept.log_scale, exact.log_scale, 1e-9);
  EXPECT_NEAR(std::abs(kept.distribution.mode().dot(exact.distribution.mode())), 1.0, 1e-12);
}

TEST(Bingham, RefusesASharpnessRatioThatIsNoRatio) {
  const SharpAndWide f = poseAndGirdle();
  for (const double ratio : {-1.0, 0.5, std::nan(""), std::numeric_limits<double>::infinity()}) {
    EXPECT_THROW(multiplyKeepingSharpFactor(f.sharp, f.wide, ratio), Error) << ratio;
  }
}

TEST(Bingham, FromExponentMatrixRecoversTheDistributionAndItsShift) {
  const BinghamDistribution b = makeDistribution(Eigen::Vector3d(-9, -4, -2), 15);
  double log_scale = 0.0;
  const BinghamDistribution copy = BinghamDistribution::fromExponentMatrix(
      b.exponentMatrix() + 3.0 * Eigen::Matrix4d::Identity(), &log_scale);
  EXPECT_NEAR(log_scale, 3.0, 1e-12);
  EXPECT_TRUE(copy.concentrations().isApprox(b.concentrations(), 1e-12));
  EXPECT_NEAR(std::abs(copy.mode().dot(b.mode())), 1.0, 1e-12);
  Eigen::Matrix4d bad = Eigen::Matrix4d::Zero();
  bad(1, 2) = NAN;
  EXPECT_THROW(BinghamDistribution::fromExponentMatrix(bad), Error);
}

}  // namespace
}  // namespace vdc
