#include "view_direction_classification/informativeness/informativeness.h"

#include <gtest/gtest.h>

#include <cmath>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

TEST(ViewKlDivergence, IsMinusLogOfTheTrueViewsProbability) {
  Eigen::VectorXd p_sum(3);
  p_sum << 0.2, 0.5, 0.3;
  EXPECT_DOUBLE_EQ(viewKlDivergence(p_sum, 1), std::log(2.0));
  EXPECT_DOUBLE_EQ(viewKlDivergence(p_sum, 0), -std::log(0.2));
  p_sum << 1.0, 0.0, 0.0;
  EXPECT_DOUBLE_EQ(viewKlDivergence(p_sum, 0), 0.0);
  // A view ruled out completely stays finite: -ln of the documented floor.
  EXPECT_DOUBLE_EQ(viewKlDivergence(p_sum, 2), -std::log(kKlProbabilityFloor));
  EXPECT_THROW(viewKlDivergence(p_sum, 3), Error);
  EXPECT_THROW(viewKlDivergence(p_sum, -1), Error);
}

TEST(ViewInformativeness, ScoresRankingAndConfusionOfHandMadeClouds) {
  auto cloud = [](int view, double a, double b, double c) {
    Eigen::VectorXd p(3);
    p << a, b, c;
    return CloudPrediction{view, p};
  };
  // View 0: two clouds with p(0) = 0.5 and 0.25; view 2: one cloud with p(2) = 0.8; view 1: none.
  const std::vector<CloudPrediction> clouds = {cloud(0, 0.5, 0.5, 0.0), cloud(2, 0.1, 0.1, 0.8),
                                               cloud(0, 0.25, 0.25, 0.5)};
  const ViewInformativeness result = computeViewInformativeness(clouds, 3);
  ASSERT_EQ(result.view_scores.size(), 3);
  EXPECT_NEAR(result.view_scores(0), 0.5 * (std::log(2.0) + std::log(4.0)), 1e-12);
  EXPECT_EQ(result.view_scores(1), -1.0);
  EXPECT_NEAR(result.view_scores(2), -std::log(0.8), 1e-12);
  EXPECT_EQ(result.ranking, (std::vector<int>{2, 0}));  // most informative first, no view 1

  ASSERT_EQ(result.confusion.rows(), 3);
  ASSERT_EQ(result.confusion.cols(), 3);
  EXPECT_NEAR(result.confusion(0, 0), 0.375, 1e-12);
  EXPECT_NEAR(result.confusion(0, 1), 0.375, 1e-12);
  EXPECT_NEAR(result.confusion(0, 2), 0.25, 1e-12);
  for (int m = 0; m < 3; ++m) EXPECT_NEAR(result.confusion(1, m), 1.0 / 3.0, 1e-12);
  EXPECT_NEAR(result.confusion(2, 2), 0.8, 1e-12);
}

TEST(ViewInformativeness, NoCloudsGivesNoRankingAndUniformConfusion) {
  const ViewInformativeness result = computeViewInformativeness({}, 2);
  EXPECT_TRUE(result.ranking.empty());
  EXPECT_EQ(result.view_scores, Eigen::VectorXd::Constant(2, -1.0));
  EXPECT_EQ(result.confusion, Eigen::MatrixXd::Constant(2, 2, 0.5));
}

TEST(ViewInformativeness, RefusesInconsistentClouds) {
  Eigen::VectorXd p(2);
  p << 0.5, 0.5;
  EXPECT_THROW(computeViewInformativeness({CloudPrediction{2, p}}, 2), Error);
  EXPECT_THROW(computeViewInformativeness({CloudPrediction{0, p}}, 3), Error);
  EXPECT_THROW(computeViewInformativeness({}, 0), Error);
}

TEST(FeatureKlDivergences, AreMinusLogOfEachFeaturesTrueView) {
  Eigen::MatrixXf P(2, 2);
  P << 0.25f, 0.75f, 1.0f, 0.0f;
  Eigen::VectorXi labels(2);
  labels << 0, 1;
  const Eigen::VectorXf kl = featureKlDivergences(P, labels);
  EXPECT_NEAR(kl(0), std::log(4.0f), 1e-6f);
  EXPECT_NEAR(kl(1), -std::log(kKlProbabilityFloor), 1e-4);
  labels(1) = 2;
  EXPECT_THROW(featureKlDivergences(P, labels), Error);
}

// Three surface points far apart; radius 0.5 (exactly representable, so the boundary is exact).
class ScoreMatrixScene : public ::testing::Test {
 protected:
  void SetUp() override {
    surface = {{0, 0, 0}, {10, 0, 0}, {0, 10, 0}};
    features.positions = {{0.25f, 0, 0},      // s0, view 0, kl 1
                          {0, 0, 0.5f},       // s0, view 0, kl 3: exactly on the radius, counts
                          {0, 0, -0.5001f},   // just outside s0: ignored
                          {10, 0, 0},         // s1, view 1, kl 2
                          {10, 0.3f, 0.3f}};  // s1, view 2, kl 0.5
    features.views.resize(5);
    features.views << 0, 0, 1, 1, 2;
    features.kl.resize(5);
    features.kl << 1.0f, 3.0f, 5.0f, 2.0f, 0.5f;
  }
  std::vector<Eigen::Vector3f> surface;
  LabelledFeatureScores features;
};

TEST_F(ScoreMatrixScene, AveragesFeatureScoresPerViewWithinTheRadius) {
  const Eigen::MatrixXf K = computeScoreMatrix(surface, features, 3, 0.5);
  Eigen::MatrixXf expected(3, 3);
  expected << 2.0f, -1, -1,  //
      -1, 2.0f, 0.5f,        //
      -1, -1, -1;            // s2: no feature anywhere near, -1 for every view
  EXPECT_EQ(K, expected);
}

TEST_F(ScoreMatrixScene, RadiusBoundaryIsInclusive) {
  EXPECT_FLOAT_EQ(computeScoreMatrix(surface, features, 3, 0.5)(0, 0), 2.0f);
  EXPECT_FLOAT_EQ(computeScoreMatrix(surface, features, 3, 0.4999)(0, 0), 1.0f);
  EXPECT_FLOAT_EQ(computeScoreMatrix(surface, features, 3, 0.5002)(0, 1), 5.0f);
}

TEST_F(ScoreMatrixScene, GlobalScoresAverageTheObservedViewsOnly) {
  const Eigen::VectorXf g = globalScores(computeScoreMatrix(surface, features, 3, 0.5));
  ASSERT_EQ(g.size(), 3);
  EXPECT_FLOAT_EQ(g(0), 2.0f);
  EXPECT_FLOAT_EQ(g(1), 1.25f);
  EXPECT_FLOAT_EQ(g(2), -1.0f);
}

TEST_F(ScoreMatrixScene, RefusesInconsistentFeatures) {
  EXPECT_THROW(computeScoreMatrix(surface, features, 2, 0.5), Error);  // view 2 out of range
  EXPECT_THROW(computeScoreMatrix(surface, features, 3, 0.0), Error);
  features.kl(0) = std::nanf("");
  EXPECT_THROW(computeScoreMatrix(surface, features, 3, 0.5), Error);
  features.kl.resize(4);
  EXPECT_THROW(computeScoreMatrix(surface, features, 3, 0.5), Error);
}

TEST(ScoreMatrix, NoFeaturesGivesAllUnobservable) {
  const Eigen::MatrixXf K = computeScoreMatrix({{0, 0, 0}}, LabelledFeatureScores{}, 2);
  EXPECT_EQ(K, Eigen::MatrixXf::Constant(1, 2, -1.0f));
  EXPECT_EQ(globalScores(K), Eigen::VectorXf::Constant(1, -1.0f));
}

}  // namespace
}  // namespace vdc
