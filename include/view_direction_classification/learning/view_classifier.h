#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "view_direction_classification/learning/logistic_regression.h"

namespace vdc {

// p(D = m | f) for raw FPFH descriptors (doc/method.md section 4): descriptors are standardised
// (mean and scale stored), optionally routed to the nearest of K k-means centroids (computed in
// the standardised space), and classified by that cluster's logistic regression over M views.
class ViewClassifier {
 public:
  struct Options {
    int clusters = 1;
    MultinomialLogisticRegression::Options regression;
    std::uint32_t seed = 1;  // k-means++ seeding
  };

  ViewClassifier() = default;
  // A trained classifier from stored parts (model bundle). mean, scale: length d (scale > 0);
  // centroids: K x d (standardised space); one regression per centroid, each (d+1) x num_views.
  // Throws vdc::Error if the parts do not fit together.
  ViewClassifier(Eigen::VectorXf mean, Eigen::VectorXf scale, Eigen::MatrixXf centroids,
                 std::vector<MultinomialLogisticRegression> regressions, int num_views);

  // descriptors: n x d raw descriptors, labels in [0, num_views). Views without features are
  // allowed. Throws vdc::Error for no descriptors, mismatched sizes, labels out of range,
  // non-finite descriptors, clusters < 1 or more clusters than descriptors.
  void train(const Eigen::MatrixXf& descriptors, const Eigen::VectorXi& labels, int num_views,
             const Options& options);

  // n x M probabilities, rows sum to 1. Throws vdc::Error if untrained, for the wrong width or
  // non-finite descriptors.
  Eigen::MatrixXf predict(const Eigen::MatrixXf& descriptors) const;

  int numViews() const { return num_views_; }
  bool trained() const { return !regressions_.empty(); }
  int clusters() const { return static_cast<int>(regressions_.size()); }
  int descriptorDimension() const { return static_cast<int>(mean_.size()); }

  const Eigen::VectorXf& mean() const { return mean_; }
  const Eigen::VectorXf& scale() const { return scale_; }
  const Eigen::MatrixXf& centroids() const { return centroids_; }
  const std::vector<MultinomialLogisticRegression>& regressions() const { return regressions_; }

 private:
  Eigen::MatrixXf standardise(const Eigen::MatrixXf& descriptors) const;

  Eigen::VectorXf mean_, scale_;
  Eigen::MatrixXf centroids_;
  std::vector<MultinomialLogisticRegression> regressions_;
  int num_views_ = 0;
};

// Held-out performance of a classifier (doc/method.md section 4).
struct HeldOutMetrics {
  double accuracy = 0.0;     // fraction of features whose most probable view is the true one
  double log_loss = 0.0;     // mean -ln p(true view | f), p floored at kKlProbabilityFloor
  std::size_t features = 0;  // number of held-out features evaluated
};

// Throws vdc::Error for zero descriptors or mismatched sizes / labels out of range.
HeldOutMetrics evaluateClassifier(const ViewClassifier& classifier,
                                  const Eigen::MatrixXf& descriptors,
                                  const Eigen::VectorXi& labels);

}  // namespace vdc
