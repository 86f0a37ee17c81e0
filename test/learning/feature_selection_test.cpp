#include "view_direction_classification/learning/feature_selection.h"

#include <gtest/gtest.h>

#include <cmath>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

TEST(FeatureSelection, EntropyOfHandMadeRows) {
  Eigen::MatrixXf P(3, 4);
  P << 1, 0, 0, 0,                 // certain: 0
      0.25f, 0.25f, 0.25f, 0.25f,  // uniform: ln 4
      0.5f, 0.5f, 0, 0;            // two-way: ln 2
  const Eigen::VectorXf H = rowEntropies(P);
  EXPECT_FLOAT_EQ(H(0), 0.0f);
  EXPECT_NEAR(H(1), std::log(4.0f), 1e-6f);
  EXPECT_NEAR(H(2), std::log(2.0f), 1e-6f);
}

TEST(FeatureSelection, MostCertainFeaturesAreSortedByEntropyThenIndex) {
  Eigen::MatrixXf P(5, 2);
  P << 0.5f, 0.5f,  // 0: ln 2 (highest)
      0.9f, 0.1f,   // 1
      1, 0,         // 2: 0
      0.1f, 0.9f,   // 3: same entropy as 1, higher index
      0, 1;         // 4: 0, same as 2
  EXPECT_EQ(mostCertainFeatures(P, 3), (std::vector<int>{2, 4, 1}));
  EXPECT_EQ(mostCertainFeatures(P, 10), (std::vector<int>{2, 4, 1, 3, 0}));
  EXPECT_THROW(mostCertainFeatures(P, 0), Error);
}

TEST(FeatureSelection, SummedDistributionNormalisesTheMostCertainRows) {
  Eigen::MatrixXf P(3, 3);
  P << 1.0f / 3, 1.0f / 3, 1.0f / 3,  // uniform: left out with n_feat = 2
      0.8f, 0.2f, 0,                  //
      0, 0, 1;                        //
  const Eigen::VectorXd p_sum = summedDistribution(P, 2);
  EXPECT_NEAR(p_sum(0), 0.4, 1e-7);
  EXPECT_NEAR(p_sum(1), 0.1, 1e-7);
  EXPECT_NEAR(p_sum(2), 0.5, 1e-7);
  const Eigen::VectorXd all = summedDistribution(P, 50);  // fewer rows than n_feat: all of them
  EXPECT_NEAR(all.sum(), 1.0, 1e-12);
  EXPECT_NEAR(all(2), (1.0 / 3 + 1.0) / 3.0, 1e-7);
}

TEST(FeatureSelection, RefusesEmptyOrInvalidDistributions) {
  EXPECT_THROW(summedDistribution(Eigen::MatrixXf(0, 4)), Error);
  EXPECT_THROW(summedDistribution(Eigen::MatrixXf::Zero(2, 4)), Error);  // sums to zero
  Eigen::MatrixXf P = Eigen::MatrixXf::Constant(2, 2, 0.5f);
  P(1, 0) = std::nanf("");
  EXPECT_THROW(rowEntropies(P), Error);
  P(1, 0) = -0.5f;
  EXPECT_THROW(summedDistribution(P), Error);
}

}  // namespace
}  // namespace vdc
