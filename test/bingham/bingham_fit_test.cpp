#include "view_direction_classification/bingham/bingham_fit.h"
#include "view_direction_classification/bingham/bingham.h"
#include "view_direction_classification/bingham/bingham_sampler.h"
#include "view_direction_classification/common/error.h"

#include <gtest/gtest.h>
#include <Eigen/QR>

#include <cmath>
#include <random>
#include <vector>

#include "support/bingham_test_distributions.h"

namespace vdc {
namespace {

TEST(BinghamFit, ExactScatterMatrixGivesBackTheDistribution) {
  for (const Eigen::Vector3d& z :
       {Eigen::Vector3d(-1, -0.5, -0.1), Eigen::Vector3d(-30, -8, -2),
        Eigen::Vector3d(-5e4, -900, 0), Eigen::Vector3d(-1e5, -1e5, -1e5)}) {
    const BinghamDistribution truth = makeDistribution(z, 1);
    const BinghamDistribution fit = fitBinghamToScatter(truth.scatterMatrix());
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(fit.concentrations()(i), z(i), 1e-5 * std::max(1.0, std::abs(z(i))))
          << z.transpose();
    }
    // Compare exponent matrices rather than modes: with z3 = 0 the mode is not unique.
    const double scale = std::max(1.0, z.cwiseAbs().maxCoeff());
    EXPECT_LT((fit.exponentMatrix() - truth.exponentMatrix()).cwiseAbs().maxCoeff(), 1e-5 * scale)
        << z.transpose();
  }
}

TEST(BinghamFit, AStartingGuessChangesOnlyWhereNewtonStartsNotTheFit) {
  // A close guess (what a mixture reduction passes), one in another order, a far one and a
  // non-finite one must all end at the fit from the default start, to the solver's tolerance.
  const Eigen::Vector3d z(-400, -60, -3);
  const BinghamDistribution truth = makeDistribution(z, 2);
  const BinghamDistribution reference = fitBinghamToScatter(truth.scatterMatrix());
  for (const Eigen::Vector3d& guess :
       {Eigen::Vector3d(-390, -62, -3.1), Eigen::Vector3d(-3.1, -390, -62),
        Eigen::Vector3d(-1e5, -1e5, -1e5), Eigen::Vector3d(NAN, -1, -1)}) {
    const BinghamDistribution fit = fitBinghamToScatter(truth.scatterMatrix(), guess);
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(fit.concentrations()(i), reference.concentrations()(i),
                  1e-6 * std::abs(reference.concentrations()(i)))
          << "guess " << guess.transpose();
    }
  }
}

TEST(BinghamFit, RecoversTheParametersOfSampledData) {
  const BinghamDistribution truth = makeDistribution(Eigen::Vector3d(-50, -20, -4), 2);
  std::mt19937_64 generator(3);
  const std::vector<Eigen::Vector4d> samples = BinghamSampler(truth).sample(20000, generator);
  const BinghamDistribution fit = fitBingham(samples);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(fit.concentrations()(i), truth.concentrations()(i),
                0.05 * std::abs(truth.concentrations()(i)));
    EXPECT_GT(std::abs(fit.axis(i).dot(truth.axis(i))), 0.99) << i;
  }
  EXPECT_GT(std::abs(fit.mode().dot(truth.mode())), 0.999);
}

TEST(BinghamFit, WeightsActLikeRepeatedSamples) {
  const std::vector<Eigen::Vector4d> samples{
      Eigen::Vector4d(1, 0, 0, 0), Eigen::Vector4d(0.8, 0.6, 0, 0), Eigen::Vector4d(0.8, 0, 0.6, 0),
      Eigen::Vector4d(0.6, 0, 0, 0.8)};
  const std::vector<Eigen::Vector4d> repeated{samples[0], samples[0], samples[1], samples[2],
                                              samples[3]};
  EXPECT_TRUE(weightedScatterMatrix(samples, {2, 1, 1, 1})
                  .isApprox(weightedScatterMatrix(repeated), 1e-14));
}

TEST(BinghamFit, IdenticalSamplesGiveTheBoundedConcentration) {
  const std::vector<Eigen::Vector4d> samples(3, Eigen::Vector4d(0, 1, 0, 0));
  const BinghamDistribution fit = fitBingham(samples);
  EXPECT_NEAR(std::abs(fit.mode()(1)), 1.0, 1e-12);
  EXPECT_NEAR(fit.concentrations()(2), -kMaxFittedConcentration, 1e-3 * kMaxFittedConcentration);
}

TEST(BinghamFit, RejectsBadInput) {
  EXPECT_THROW(fitBingham(std::vector<Eigen::Vector4d>{}), Error);
  EXPECT_THROW(fitBingham(std::vector<Eigen::Vector4d>{Eigen::Vector4d(1, 1, 0, 0)}), Error);
  EXPECT_THROW(fitBingham(std::vector<Eigen::Vector4d>{Eigen::Vector4d(NAN, 0, 0, 0)}), Error);
  EXPECT_THROW(fitBingham(std::vector<Eigen::Vector4d>{Eigen::Vector4d(1, 0, 0, 0)}, {-1.0}),
               Error);
  EXPECT_THROW(fitBingham(std::vector<Eigen::Vector4d>{Eigen::Vector4d(1, 0, 0, 0)}, {0.0}), Error);
  EXPECT_THROW(fitBingham(std::vector<Eigen::Vector4d>{Eigen::Vector4d(1, 0, 0, 0)}, {1.0, 2.0}),
               Error);
  EXPECT_THROW(fitBinghamToScatter(Eigen::Matrix4d::Zero()), Error);
  EXPECT_THROW(fitBinghamToScatter(Eigen::Matrix4d(-Eigen::Matrix4d::Identity())), Error);
  Eigen::Matrix4d asymmetric = Eigen::Matrix4d::Identity();
  asymmetric(0, 1) = 0.5;
  EXPECT_THROW(fitBinghamToScatter(asymmetric), Error);
  Eigen::Matrix4d nan = Eigen::Matrix4d::Identity();
  nan(2, 2) = NAN;
  EXPECT_THROW(fitBinghamToScatter(nan), Error);
}

}  // namespace
}  // namespace vdc
