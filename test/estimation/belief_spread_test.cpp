#include "view_direction_classification/estimation/belief_spread.h"

#include <gtest/gtest.h>

#include <Eigen/QR>
#include <cmath>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/quaternion.h"

namespace vdc {
namespace {

// A Bingham concentrated around `mode` with equal concentrations -k: its density falls as
// exp(-k sin^2(theta / 2)) ~ exp(-k theta^2 / 4) with the rotation angle theta, so the rotation
// vector is Gaussian with variance 2 / k per axis and the 90 % cone is sqrt(6.2514 * 2 / k)
// (the chi-square quantile of three degrees of freedom).
BinghamMixture isotropic(const Eigen::Vector4d& mode, double k) {
  // The first Householder column is +-mode; the other three are orthonormal to it.
  const Eigen::Matrix4d q = Eigen::HouseholderQR<Eigen::Vector4d>(mode).householderQ();
  const BinghamDistribution::Axes axes = q.rightCols<3>();
  return BinghamMixture({1.0}, {BinghamDistribution(Eigen::Vector3d(-k, -k, -k), axes)});
}

TEST(BeliefSpread, ConeAndCovarianceOfASharpBinghamMatchItsGaussianLimit) {
  const Eigen::Vector4d mode = quaternionFromAxisAngle(Eigen::Vector3d(1, 2, 3).normalized(), 0.9);
  const double k = 400.0;
  const BeliefSpread spread = beliefSpread(isotropic(mode, k), mode, 4000);
  const double sigma2 = 2.0 / k;
  EXPECT_NEAR(spread.cone90, std::sqrt(6.2514 * sigma2), 0.05 * std::sqrt(6.2514 * sigma2));
  EXPECT_NEAR(spread.cone50, std::sqrt(2.366 * sigma2), 0.05 * std::sqrt(2.366 * sigma2));
  EXPECT_LT(spread.cone50, spread.cone90);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(spread.covariance(i, i), sigma2, 0.1 * sigma2);
    for (int j = 0; j < i; ++j) EXPECT_NEAR(spread.covariance(i, j), 0.0, 0.1 * sigma2);
  }
}

TEST(BeliefSpread, TheUniformBeliefSpreadsOverMostOfTheRotations) {
  // The rotation angle of a uniform rotation has density (1 - cos t) / pi on [0, pi]; its 90 %
  // quantile solves (t - sin t) / pi = 0.9: 2.984 rad (171 deg).
  const BeliefSpread spread = beliefSpread(BinghamMixture(), Eigen::Vector4d(1, 0, 0, 0), 4000);
  EXPECT_NEAR(spread.cone90, 2.984, 0.03);
}

TEST(BeliefSpread, RefusesTooFewSamplesOrANonUnitMap) {
  EXPECT_THROW(beliefSpread(BinghamMixture(), Eigen::Vector4d(1, 0, 0, 0), 5), Error);
  EXPECT_THROW(beliefSpread(BinghamMixture(), Eigen::Vector4d(2, 0, 0, 0)), Error);
}

}  // namespace
}  // namespace vdc
