#include "view_direction_classification/learning/logistic_regression.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

// n samples per class around the given centres, Gaussian spread `sigma`, fixed seed.
void makeBlobs(const Eigen::MatrixXf& centres, int per_class, float sigma, std::uint32_t seed,
               Eigen::MatrixXf* X, Eigen::VectorXi* labels) {
  std::mt19937 rng(seed);
  std::normal_distribution<float> noise(0.0f, sigma);
  const int classes = static_cast<int>(centres.rows());
  X->resize(classes * per_class, centres.cols());
  labels->resize(classes * per_class);
  for (int c = 0; c < classes; ++c) {
    for (int k = 0; k < per_class; ++k) {
      const int row = c * per_class + k;
      for (int j = 0; j < centres.cols(); ++j) (*X)(row, j) = centres(c, j) + noise(rng);
      (*labels)(row) = c;
    }
  }
}

TEST(MultinomialLogisticRegression, LossGradientMatchesFiniteDifferences) {
  std::mt19937 rng(7);
  std::normal_distribution<double> normal(0.0, 1.0);
  const int n = 40, d = 5, classes = 4;
  Eigen::MatrixXf X(n, d);
  Eigen::VectorXi labels(n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < d; ++j) X(i, j) = static_cast<float>(normal(rng));
    labels(i) = i % classes;
  }
  Eigen::MatrixXd W(d + 1, classes);
  for (int i = 0; i < W.size(); ++i) W(i) = 0.5 * normal(rng);
  const double l2 = 0.3;

  Eigen::MatrixXd gradient;
  MultinomialLogisticRegression::loss(W, X, labels, l2, &gradient);
  ASSERT_EQ(gradient.rows(), d + 1);
  ASSERT_EQ(gradient.cols(), classes);
  const double h = 1e-6;
  for (int i = 0; i < W.size(); ++i) {
    Eigen::MatrixXd plus = W, minus = W;
    plus(i) += h;
    minus(i) -= h;
    const double numeric = (MultinomialLogisticRegression::loss(plus, X, labels, l2, nullptr) -
                            MultinomialLogisticRegression::loss(minus, X, labels, l2, nullptr)) /
                           (2 * h);
    EXPECT_NEAR(gradient(i), numeric, 1e-7) << "entry " << i;
  }
}

TEST(MultinomialLogisticRegression, LossDoesNotRegulariseTheBias) {
  Eigen::MatrixXf X = Eigen::MatrixXf::Zero(2, 1);
  Eigen::VectorXi labels(2);
  labels << 0, 1;
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(2, 2);
  W(1, 0) = 3.0;  // bias only: shifting both biases changes nothing, the penalty must be 0
  W(1, 1) = 3.0;
  EXPECT_NEAR(MultinomialLogisticRegression::loss(W, X, labels, 10.0, nullptr), std::log(2.0),
              1e-12);
}

TEST(MultinomialLogisticRegression, LossStaysFiniteForHugeScores) {
  Eigen::MatrixXf X(1, 1);
  X << 1.0f;
  Eigen::VectorXi labels(1);
  labels << 1;
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(2, 2);
  W(0, 0) = 1e4;  // exp(1e4) overflows without log-sum-exp
  Eigen::MatrixXd gradient;
  const double value = MultinomialLogisticRegression::loss(W, X, labels, 0.0, &gradient);
  EXPECT_NEAR(value, 1e4, 1e-6);
  EXPECT_TRUE(gradient.allFinite());
}

TEST(MultinomialLogisticRegression, RecoversSeparableClasses) {
  Eigen::MatrixXf centres(3, 2);
  centres << 0, 4, 4, -2, -4, -2;
  Eigen::MatrixXf X;
  Eigen::VectorXi labels;
  makeBlobs(centres, 50, 0.5f, 3, &X, &labels);
  MultinomialLogisticRegression model;
  model.fit(X, labels, 3, {});
  const Eigen::MatrixXf P = model.predictProbabilities(X);
  ASSERT_EQ(P.rows(), X.rows());
  ASSERT_EQ(P.cols(), 3);
  for (int i = 0; i < P.rows(); ++i) {
    Eigen::Index predicted;
    P.row(i).maxCoeff(&predicted);
    EXPECT_EQ(predicted, labels(i)) << "sample " << i;
    EXPECT_NEAR(P.row(i).sum(), 1.0f, 1e-5f);
    EXPECT_GT(P(i, labels(i)), 0.9f);
  }
}

TEST(MultinomialLogisticRegression, ProbabilitiesAreCalibratedOnOverlappingClasses) {
  // Two 1-D Gaussians N(-1, 1) and N(+1, 1) with equal priors: the true posterior is
  // p(1 | x) = 1 / (1 + exp(-2x)). A well-fitted model reproduces it.
  Eigen::MatrixXf centres(2, 1);
  centres << -1, 1;
  Eigen::MatrixXf X;
  Eigen::VectorXi labels;
  makeBlobs(centres, 4000, 1.0f, 11, &X, &labels);
  MultinomialLogisticRegression model;
  MultinomialLogisticRegression::Options options;
  options.l2 = 0.0;
  model.fit(X, labels, 2, options);
  Eigen::MatrixXf probe(3, 1);
  probe << -1.0f, 0.0f, 1.0f;
  const Eigen::MatrixXf P = model.predictProbabilities(probe);
  for (int i = 0; i < 3; ++i) {
    const double expected = 1.0 / (1.0 + std::exp(-2.0 * probe(i, 0)));
    EXPECT_NEAR(P(i, 1), expected, 0.04) << "x = " << probe(i, 0);
  }
}

TEST(MultinomialLogisticRegression, ClassWithoutSamplesGetsLowProbability) {
  Eigen::MatrixXf centres(2, 2);
  centres << -3, 0, 3, 0;
  Eigen::MatrixXf X;
  Eigen::VectorXi labels;
  makeBlobs(centres, 30, 0.5f, 5, &X, &labels);
  labels = (labels.array() == 1).select(2, labels);  // classes 0 and 2 present, 1 empty
  MultinomialLogisticRegression model;
  model.fit(X, labels, 3, {});
  const Eigen::MatrixXf P = model.predictProbabilities(X);
  ASSERT_TRUE(P.allFinite());
  EXPECT_LT(P.col(1).maxCoeff(), 0.05f);
}

TEST(MultinomialLogisticRegression, TrainingIsIdenticalForAnyThreadCount) {
  Eigen::MatrixXf centres(3, 2);
  centres << 0, 1, 1, 0, -1, -1;
  Eigen::MatrixXf X;
  Eigen::VectorXi labels;
  makeBlobs(centres, 1500, 1.0f, 13, &X, &labels);  // 4500 rows: several loss blocks
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  MultinomialLogisticRegression single;
  single.fit(X, labels, 3, {});
  omp_set_num_threads(std::max(2, threads));
  MultinomialLogisticRegression parallel;
  parallel.fit(X, labels, 3, {});
  omp_set_num_threads(threads);
  EXPECT_EQ(single.weights(), parallel.weights());
}

TEST(MultinomialLogisticRegression, RefusesBadInput) {
  MultinomialLogisticRegression model;
  Eigen::MatrixXf X(0, 3);
  Eigen::VectorXi labels(0);
  EXPECT_THROW(model.fit(X, labels, 2, {}), Error);
  X = Eigen::MatrixXf::Zero(2, 3);
  labels = Eigen::VectorXi::Zero(2);
  labels(1) = 5;
  EXPECT_THROW(model.fit(X, labels, 2, {}), Error);
  labels(1) = 1;
  X(0, 0) = std::nanf("");
  EXPECT_THROW(model.fit(X, labels, 2, {}), Error);
  EXPECT_THROW(model.predictProbabilities(Eigen::MatrixXf::Zero(1, 3)), Error);  // untrained
  model.setWeights(Eigen::MatrixXd::Zero(4, 2));
  EXPECT_THROW(model.predictProbabilities(Eigen::MatrixXf::Zero(1, 2)), Error);  // width
  EXPECT_THROW(model.setWeights(Eigen::MatrixXd::Constant(4, 2, std::nan(""))), Error);
}

}  // namespace
}  // namespace vdc
