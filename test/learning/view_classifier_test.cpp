#include "view_direction_classification/learning/view_classifier.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

// A toy "FPFH" problem: 33-d non-negative descriptors, views distinguishable by which bins are
// high; the scale of the bins differs wildly (standardisation matters) and bin 32 is constant.
// Views 0..2 share one descriptor regime and 3..5 another, so K-means routing has structure.
void makeDescriptors(int views, int per_view, std::uint32_t seed, Eigen::MatrixXf* X,
                     Eigen::VectorXi* labels) {
  std::mt19937 rng(seed);
  std::normal_distribution<float> noise(0.0f, 1.0f);
  X->resize(views * per_view, 33);
  labels->resize(views * per_view);
  for (int v = 0; v < views; ++v) {
    for (int k = 0; k < per_view; ++k) {
      const int row = v * per_view + k;
      for (int j = 0; j < 32; ++j) {
        const float bin_scale = 1.0f + 50.0f * static_cast<float>(j % 3);
        const float base = (j % views == v ? 4.0f : 0.0f) + (j >= 16) * (v >= views / 2) * 6.0f;
        (*X)(row, j) = bin_scale * (base + 0.7f * noise(rng));
      }
      (*X)(row, 32) = 7.0f;
      (*labels)(row) = v;
    }
  }
}

double accuracyOf(const Eigen::MatrixXf& P, const Eigen::VectorXi& labels) {
  int correct = 0;
  for (Eigen::Index i = 0; i < P.rows(); ++i) {
    Eigen::Index best;
    P.row(i).maxCoeff(&best);
    correct += best == labels(i);
  }
  return static_cast<double>(correct) / static_cast<double>(P.rows());
}

class ViewClassifierClusters : public ::testing::TestWithParam<int> {};

TEST_P(ViewClassifierClusters, ClassifiesHeldOutViews) {
  Eigen::MatrixXf train_X, test_X;
  Eigen::VectorXi train_y, test_y;
  makeDescriptors(6, 60, 1, &train_X, &train_y);
  makeDescriptors(6, 30, 2, &test_X, &test_y);
  ViewClassifier classifier;
  ViewClassifier::Options options;
  options.clusters = GetParam();
  classifier.train(train_X, train_y, 6, options);
  ASSERT_TRUE(classifier.trained());
  EXPECT_EQ(classifier.numViews(), 6);
  EXPECT_EQ(classifier.clusters(), GetParam());
  const Eigen::MatrixXf P = classifier.predict(test_X);
  ASSERT_EQ(P.rows(), test_X.rows());
  ASSERT_EQ(P.cols(), 6);
  ASSERT_TRUE(P.allFinite());
  EXPECT_LT((P.rowwise().sum().array() - 1.0f).abs().maxCoeff(), 1e-5f);
  EXPECT_GT(accuracyOf(P, test_y), 0.9);

  const HeldOutMetrics metrics = evaluateClassifier(classifier, test_X, test_y);
  EXPECT_EQ(metrics.features, static_cast<std::size_t>(test_X.rows()));
  EXPECT_DOUBLE_EQ(metrics.accuracy, accuracyOf(P, test_y));
  EXPECT_GT(metrics.log_loss, 0.0);
  EXPECT_LT(metrics.log_loss, 0.5);
}

INSTANTIATE_TEST_SUITE_P(OneAndThreeClusters, ViewClassifierClusters, ::testing::Values(1, 3));

TEST(ViewClassifier, ConstantDimensionGetsUnitScale) {
  Eigen::MatrixXf X;
  Eigen::VectorXi y;
  makeDescriptors(3, 20, 3, &X, &y);
  ViewClassifier classifier;
  classifier.train(X, y, 3, {});
  EXPECT_FLOAT_EQ(classifier.scale()(32), 1.0f);
  EXPECT_FLOAT_EQ(classifier.mean()(32), 7.0f);
  EXPECT_GT(classifier.scale()(1), 10.0f);  // a wide bin is scaled down
}

TEST(ViewClassifier, RebuiltFromItsPartsPredictsIdentically) {
  Eigen::MatrixXf X;
  Eigen::VectorXi y;
  makeDescriptors(4, 20, 5, &X, &y);
  ViewClassifier classifier;
  ViewClassifier::Options options;
  options.clusters = 2;
  classifier.train(X, y, 4, options);
  const ViewClassifier copy(classifier.mean(), classifier.scale(), classifier.centroids(),
                            classifier.regressions(), classifier.numViews());
  EXPECT_EQ(copy.predict(X), classifier.predict(X));
}

TEST(ViewClassifier, ViewWithoutFeaturesGetsLowProbabilityNotNaN) {
  Eigen::MatrixXf X;
  Eigen::VectorXi y;
  makeDescriptors(3, 20, 6, &X, &y);
  ViewClassifier classifier;
  classifier.train(X, y, 4, {});  // view 3 has no feature
  const Eigen::MatrixXf P = classifier.predict(X);
  ASSERT_TRUE(P.allFinite());
  EXPECT_LT(P.col(3).maxCoeff(), 0.05f);
}

TEST(ViewClassifier, RefusesBadInput) {
  ViewClassifier classifier;
  EXPECT_THROW(classifier.predict(Eigen::MatrixXf::Zero(1, 33)), Error);
  EXPECT_THROW(classifier.train(Eigen::MatrixXf(0, 33), Eigen::VectorXi(0), 3, {}), Error);
  Eigen::MatrixXf X;
  Eigen::VectorXi y;
  makeDescriptors(3, 5, 7, &X, &y);
  ViewClassifier::Options options;
  options.clusters = 100;
  EXPECT_THROW(classifier.train(X, y, 3, options), Error);
  EXPECT_THROW(classifier.train(X, y, 2, {}), Error);  // label 2 out of range
  classifier.train(X, y, 3, {});
  EXPECT_THROW(classifier.predict(Eigen::MatrixXf::Zero(1, 5)), Error);
  EXPECT_THROW(classifier.predict(Eigen::MatrixXf::Constant(1, 33, std::nanf(""))), Error);
  EXPECT_THROW(evaluateClassifier(classifier, Eigen::MatrixXf(0, 33), Eigen::VectorXi(0)), Error);
  EXPECT_THROW(ViewClassifier(Eigen::VectorXf::Zero(33), Eigen::VectorXf::Zero(33),
                              classifier.centroids(), classifier.regressions(), 3),
               Error);  // zero scale
}

}  // namespace
}  // namespace vdc
