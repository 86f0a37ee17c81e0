#include "view_direction_classification/bingham/bingham_sampler.h"
#include "view_direction_classification/bingham/bingham.h"

#include <gtest/gtest.h>
#include <Eigen/QR>

#include <cmath>
#include <random>
#include <vector>

#include "support/bingham_test_distributions.h"

namespace vdc {
namespace {


Eigen::Matrix4d empiricalScatter(const std::vector<Eigen::Vector4d>& samples) {
  Eigen::Matrix4d scatter = Eigen::Matrix4d::Zero();
  for (const Eigen::Vector4d& x : samples) scatter += x * x.transpose();
  return scatter / samples.size();
}

TEST(BinghamSampler, SampleMomentsMatchTheScatterMatrixFromBroadToSharp) {
  std::mt19937_64 generator(42);
  const int count = 20000;
  for (const Eigen::Vector3d& z :
       {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(-10, -3, -0.5), Eigen::Vector3d(-400, -400, 0),
        Eigen::Vector3d(-1e5, -2e4, -5e3)}) {
    const BinghamDistribution b = makeDistribution(z, 3);
    const std::vector<Eigen::Vector4d> samples = BinghamSampler(b).sample(count, generator);
    const Eigen::Matrix4d expected = b.scatterMatrix();
    const Eigen::Matrix4d empirical = empiricalScatter(samples);
    // Each entry is a mean of values in [-1, 1] with variance <= its second moment; 5 sigma.
    for (int i = 0; i < 4; ++i) {
      for (int j = 0; j < 4; ++j) {
        const double sigma =
            std::sqrt(std::max(expected(i, i) * expected(j, j), 1e-12) / count) + 1e-9;
        EXPECT_NEAR(empirical(i, j), expected(i, j), 5.0 * sigma)
            << "z = " << z.transpose() << " entry " << i << "," << j;
      }
    }
    for (const Eigen::Vector4d& x : samples) ASSERT_NEAR(x.norm(), 1.0, 1e-12);
  }
}

TEST(BinghamSampler, AxisMomentsOfAVeryConcentratedDistributionAreItsTinyVariances) {
  const BinghamDistribution b = makeDistribution(Eigen::Vector3d(-1e5, -1e4, -1e3), 4);
  std::mt19937_64 generator(5);
  const std::vector<Eigen::Vector4d> samples = BinghamSampler(b).sample(20000, generator);
  const Eigen::Vector3d expected = b.axisMoments();
  for (int i = 0; i < 3; ++i) {
    double moment = 0.0;
    for (const Eigen::Vector4d& x : samples) moment += std::pow(b.axis(i).dot(x), 2);
    moment /= samples.size();
    // (v.x)^2 is about chi-square with one degree of freedom: relative sd sqrt(2 / n) = 1 %.
    EXPECT_NEAR(moment, expected(i), 0.05 * expected(i)) << i;
  }
}

TEST(BinghamSampler, EnvelopeBoundStaysBelowTheKentGaneiberMardiaLimit) {
  EXPECT_NEAR(BinghamSampler(BinghamDistribution()).envelopeBound(), 1.0, 1e-12);
  const double sharp =
      BinghamSampler(makeDistribution(Eigen::Vector3d(-1e6, -1e6, -1e6), 1)).envelopeBound();
  EXPECT_GT(sharp, 1.0);
  EXPECT_LT(sharp, 16.0 * std::exp(-1.5) + 1e-9);
}

TEST(BinghamSampler, SameSeedGivesSameSamples) {
  const BinghamSampler sampler(makeDistribution(Eigen::Vector3d(-5, -2, -1), 2));
  std::mt19937_64 first(9), second(9);
  EXPECT_EQ(sampler.sample(10, first), sampler.sample(10, second));
}

}  // namespace
}  // namespace vdc
