#include "view_direction_classification/bingham/bingham_normalizer.h"
#include "support/random_unit_quaternions.h"
#include "view_direction_classification/common/error.h"

#include <gtest/gtest.h>
#include <boost/math/special_functions/bessel.hpp>

#include <cmath>
#include <random>
#include <vector>

namespace vdc {
namespace {

constexpr double kTwoPiSquared = 2.0 * M_PI * M_PI;

// F(-k,-k,0) = 2 pi^2 (1 - e^-k) / k: the one closed form of Wood's integral.
double girdleClosedForm(double k) { return -kTwoPiSquared * std::expm1(-k) / k; }

TEST(BinghamNormalizer, UniformIsTheAreaOfTheThreeSphere) {
  EXPECT_NEAR(binghamNormalizer(Eigen::Vector3d::Zero()), kTwoPiSquared, 1e-12 * kTwoPiSquared);
}

TEST(BinghamNormalizer, MatchesTheClosedFormWithinOneInABillionFromTinyToHugeConcentrations) {
  for (double k = 1e-6; k <= 1e5 * 1.0001; k *= std::sqrt(10.0)) {
    const double expected = girdleClosedForm(k);
    // The closed form holds for every pairing of the concentrations.
    for (const Eigen::Vector3d& z : {Eigen::Vector3d(-k, -k, 0.0), Eigen::Vector3d(0.0, -k, -k),
                                     Eigen::Vector3d(-k, 0.0, -k)}) {
      const double value = binghamNormalizer(z);
      EXPECT_LE(std::abs(value - expected) / expected, 1e-9) << "k = " << k << " z = " << z;
    }
  }
}

TEST(BinghamNormalizer, MatchesTheReferenceSeriesValues) {
  struct Reference {
    Eigen::Vector3d z;
    double value;
    double half_last_digit;
  };
  const std::vector<Reference> references{
      {{-1, -1, 0}, 12.4776, 5e-5},
      {{-5, -3, -1}, 3.5429, 5e-5},
      {{-10, -4, -0.5}, 2.54959, 5e-6},
      {{-20, -20, -2}, 0.473232, 5e-7},
  };
  for (const Reference& reference : references) {
    EXPECT_NEAR(binghamNormalizer(reference.z), reference.value, reference.half_last_digit)
        << reference.z.transpose();
  }
}

TEST(BinghamNormalizer, AgreesWithMonteCarloIntegrationOverTheSphere) {
  const std::vector<Eigen::Vector3d> cases{{-2, -1, -0.5}, {-8, -3, 0}, {-30, -0.1, -0.1}};
  const int samples = 200000;
  const std::vector<Eigen::Vector4d> points = test::randomUnitQuaternionsFromSeed(samples, 7);
  for (const Eigen::Vector3d& z : cases) {
    double sum = 0.0, sum_squares = 0.0;
    for (const Eigen::Vector4d& x : points) {
      const double value = std::exp(z(0) * x(0) * x(0) + z(1) * x(1) * x(1) + z(2) * x(2) * x(2));
      sum += value;
      sum_squares += value * value;
    }
    const double mean = sum / samples;
    const double standard_error = std::sqrt((sum_squares / samples - mean * mean) / samples);
    EXPECT_NEAR(binghamNormalizer(z), kTwoPiSquared * mean, 4.0 * kTwoPiSquared * standard_error)
        << z.transpose();
  }
}

TEST(BinghamNormalizer, DoesNotDependOnTheOrderOfConcentrations) {
  const double reference = binghamNormalizer(Eigen::Vector3d(-300, -20, -1));
  EXPECT_NEAR(binghamNormalizer(Eigen::Vector3d(-1, -300, -20)), reference, 1e-10 * reference);
  EXPECT_NEAR(binghamNormalizer(Eigen::Vector3d(-20, -1, -300)), reference, 1e-10 * reference);
}

TEST(BinghamNormalizer, GradientMatchesCentralFiniteDifferences) {
  const std::vector<Eigen::Vector3d> cases{{0, 0, 0},         {-1, -1, 0},       {-5, -3, -1},
                                           {-200, -50, -0.3}, {-1e4, -1e4, -10}, {-9e4, -1, 0}};
  for (const Eigen::Vector3d& z : cases) {
    const BinghamNormalizer f = binghamNormalizerWithGradient(z);
    EXPECT_NEAR(f.value, binghamNormalizer(z), 1e-10 * f.value);
    for (int i = 0; i < 3; ++i) {
      const double h = 1e-4 * std::max(1.0, std::abs(z(i)));
      Eigen::Vector3d lower = z, upper = z;
      lower(i) -= h;
      upper(i) = std::min(0.0, upper(i) + h);  // F is only defined for z <= 0
      const double difference =
          (binghamNormalizer(upper) - binghamNormalizer(lower)) / (upper(i) - lower(i));
      // The one-sided difference at z_i = 0 is first-order accurate only.
      const double tolerance = z(i) == 0.0 ? 1e-3 : 1e-6;
      EXPECT_NEAR(f.gradient(i), difference, tolerance * std::abs(f.gradient(i)))
          << "z = " << z.transpose() << ", i = " << i;
    }
  }
}

TEST(BinghamNormalizer, GradientEntriesArePositiveSecondMomentsSummingBelowF) {
  // dF/dz_i = F E[x_i^2] and E[x_1^2] + E[x_2^2] + E[x_3^2] = 1 - E[x_4^2] < 1.
  const BinghamNormalizer f = binghamNormalizerWithGradient(Eigen::Vector3d(-40, -7, -2));
  EXPECT_GT(f.gradient.minCoeff(), 0.0);
  EXPECT_LT(f.gradient.sum(), f.value);
}

TEST(BinghamNormalizer, UpperBoundHoldsEverywhereAndIsExactForGirdles) {
  std::mt19937 generator(7);
  std::uniform_real_distribution<double> log_magnitude(-3.0, 5.0);
  for (int trial = 0; trial < 300; ++trial) {
    Eigen::Vector3d z;
    for (int i = 0; i < 3; ++i) z(i) = -std::pow(10.0, log_magnitude(generator));
    if (trial % 3 == 0) z(trial % 2) = 0.0;  // also concentrations at the boundary
    EXPECT_LE(std::log(binghamNormalizer(z)), binghamLogNormalizerUpperBound(z) + 1e-12)
        << "z = " << z.transpose();
  }
  // F(z2, z2, 0) is the bound itself, whatever the order.
  EXPECT_NEAR(binghamLogNormalizerUpperBound(Eigen::Vector3d(0.0, -30.0, -30.0)),
              std::log(girdleClosedForm(30.0)), 1e-12);
  // The bound tightens with concentration: a mixture product prunes with it.
  EXPECT_LT(binghamLogNormalizerUpperBound(Eigen::Vector3d(-1e4, -1e3, -1e2)),
            std::log(kTwoPiSquared) - 6.0);
  EXPECT_NEAR(binghamLogNormalizerUpperBound(Eigen::Vector3d::Zero()), std::log(kTwoPiSquared),
              1e-15);
  EXPECT_THROW(binghamLogNormalizerUpperBound(Eigen::Vector3d(-1.0, 0.5, 0.0)), Error);
}

TEST(BinghamNormalizer, ScaledBesselFunctionsMatchReferenceValuesAndJoinTheAsymptoticBranch) {
  EXPECT_NEAR(besselI0Scaled(0.0), 1.0, 1e-15);
  EXPECT_NEAR(besselI0Scaled(1.0), 0.46575960759364043, 1e-15);
  EXPECT_NEAR(besselI1Scaled(1.0), 0.2079104153497085, 1e-15);
  EXPECT_NEAR(besselI1Scaled(-1.0), -0.2079104153497085, 1e-15);
  // At and beyond the switch to Hankel's series (x = 500), compare with Boost's unscaled values
  // (still finite there) and with the series' leading terms far out.
  for (double x : {500.0, 650.0}) {
    EXPECT_NEAR(besselI0Scaled(x), boost::math::cyl_bessel_i(0, x) * std::exp(-x),
                1e-14 * besselI0Scaled(x));
    EXPECT_NEAR(besselI1Scaled(x), boost::math::cyl_bessel_i(1, x) * std::exp(-x),
                1e-14 * besselI1Scaled(x));
  }
  const double far = 1e6;
  const double leading = (1.0 + 1.0 / (8.0 * far)) / std::sqrt(2.0 * M_PI * far);
  EXPECT_NEAR(besselI0Scaled(far), leading, 1e-12 * leading);
}

}  // namespace
}  // namespace vdc
