#include "view_direction_classification/learning/view_classifier.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/learning/kmeans.h"
#include "view_direction_classification/learning/log_loss.h"

namespace vdc {
namespace {

// A descriptor dimension whose standard deviation is below this fraction of max(1, |mean|) is
// treated as constant and gets scale 1: dividing by float rounding noise would blow it up.
constexpr double kConstantDimensionTolerance = 1e-6;

void checkLabelled(const Eigen::MatrixXf& descriptors, const Eigen::VectorXi& labels, int num_views,
                   const char* what) {
  if (descriptors.rows() == 0) {
    throw Error(std::string("view classifier: there are no ") + what + " descriptors (0 rows)");
  }
  if (labels.size() != descriptors.rows()) {
    throw Error(std::string("view classifier: ") + std::to_string(descriptors.rows()) + " " + what +
                " descriptors but " + std::to_string(labels.size()) + " labels");
  }
  for (Eigen::Index i = 0; i < labels.size(); ++i) {
    if (labels(i) < 0 || labels(i) >= num_views) {
      throw Error(std::string("view classifier: label ") + std::to_string(labels(i)) + " of " +
                  what + " descriptor " + std::to_string(i) + " is outside [0, " +
                  std::to_string(num_views) + ")");
    }
  }
}

}  // namespace

ViewClassifier::ViewClassifier(Eigen::VectorXf mean, Eigen::VectorXf scale,
                               Eigen::MatrixXf centroids,
                               std::vector<MultinomialLogisticRegression> regressions,
                               int num_views) {
  const Eigen::Index d = mean.size();
  if (num_views < 1) {
    throw Error("view classifier: the number of views must be at least 1, got " +
                std::to_string(num_views));
  }
  if (d < 1 || scale.size() != d) {
    throw Error("view classifier: mean has " + std::to_string(d) + " entries and scale " +
                std::to_string(scale.size()) + ", expected the same positive number");
  }
  if (!mean.allFinite() || !scale.allFinite() || (scale.array() <= 0.0f).any()) {
    throw Error("view classifier: mean and scale must be finite and scale positive");
  }
  if (regressions.empty() || centroids.rows() != static_cast<Eigen::Index>(regressions.size()) ||
      centroids.cols() != d || !centroids.allFinite()) {
    throw Error("view classifier: " + std::to_string(centroids.rows()) + " x " +
                std::to_string(centroids.cols()) + " centroids do not fit " +
                std::to_string(regressions.size()) + " regressions on " + std::to_string(d) +
                " dimensions");
  }
  for (const auto& regression : regressions) {
    if (!regression.trained() || regression.inputDimension() != d ||
        regression.numClasses() != num_views) {
      throw Error("view classifier: a regression has weights " +
                  std::to_string(regression.weights().rows()) + " x " +
                  std::to_string(regression.weights().cols()) + ", expected " +
                  std::to_string(d + 1) + " x " + std::to_string(num_views));
    }
  }
  mean_ = std::move(mean);
  scale_ = std::move(scale);
  centroids_ = std::move(centroids);
  regressions_ = std::move(regressions);
  num_views_ = num_views;
}

void ViewClassifier::train(const Eigen::MatrixXf& descriptors, const Eigen::VectorXi& labels,
                           int num_views, const Options& options) {
  if (num_views < 1) {
    throw Error("view classifier: the number of views must be at least 1, got " +
                std::to_string(num_views));
  }
  checkLabelled(descriptors, labels, num_views, "training");
  if (!descriptors.allFinite()) {
    throw Error("view classifier: the training descriptors contain NaN or infinite values");
  }
  if (options.clusters < 1 || options.clusters > descriptors.rows()) {
    throw Error(
        "view classifier: clusters must be between 1 and the number of training "
        "descriptors (" +
        std::to_string(descriptors.rows()) + "), got " + std::to_string(options.clusters));
  }

  const Eigen::MatrixXd data = descriptors.cast<double>();
  const Eigen::VectorXd mean = data.colwise().mean().transpose();
  const Eigen::VectorXd variance =
      (data.rowwise() - mean.transpose()).array().square().colwise().mean().transpose();
  Eigen::VectorXf scale(mean.size());
  for (Eigen::Index j = 0; j < mean.size(); ++j) {
    const double sd = std::sqrt(variance(j));
    const bool constant = sd <= kConstantDimensionTolerance * std::max(1.0, std::abs(mean(j)));
    scale(j) = constant ? 1.0f : static_cast<float>(sd);
  }
  mean_ = mean.cast<float>();
  scale_ = scale;
  num_views_ = num_views;
  regressions_.clear();

  const Eigen::MatrixXf standardised = standardise(descriptors);
  if (options.clusters == 1) {
    // One cluster: no k-means; its centroid is the origin of the standardised space (the mean).
    centroids_ = Eigen::MatrixXf::Zero(1, descriptors.cols());
  } else {
    KMeansOptions kmeans;
    kmeans.seed = options.seed;
    centroids_ = kMeans(standardised, options.clusters, kmeans);
  }
  const Eigen::VectorXi cluster = nearestCentroids(centroids_, standardised);

  std::vector<MultinomialLogisticRegression> regressions(
      static_cast<std::size_t>(options.clusters));
  for (int c = 0; c < options.clusters; ++c) {
    std::vector<Eigen::Index> rows;
    for (Eigen::Index i = 0; i < cluster.size(); ++i) {
      if (cluster(i) == c) rows.push_back(i);
    }
    if (rows.empty()) {
      // Cannot happen on k-means' own data, but the rule must hold: a cluster without samples
      // predicts the uniform distribution rather than failing.
      regressions[static_cast<std::size_t>(c)].setWeights(
          Eigen::MatrixXd::Zero(descriptors.cols() + 1, num_views));
      continue;
    }
    Eigen::MatrixXf X(static_cast<Eigen::Index>(rows.size()), descriptors.cols());
    Eigen::VectorXi y(static_cast<Eigen::Index>(rows.size()));
    for (std::size_t r = 0; r < rows.size(); ++r) {
      X.row(static_cast<Eigen::Index>(r)) = standardised.row(rows[r]);
      y(static_cast<Eigen::Index>(r)) = labels(rows[r]);
    }
    regressions[static_cast<std::size_t>(c)].fit(X, y, num_views, options.regression);
  }
  regressions_ = std::move(regressions);
}

Eigen::MatrixXf ViewClassifier::standardise(const Eigen::MatrixXf& descriptors) const {
  return (descriptors.rowwise() - mean_.transpose()).array().rowwise() / scale_.transpose().array();
}

Eigen::MatrixXf ViewClassifier::predict(const Eigen::MatrixXf& descriptors) const {
  if (!trained()) throw Error("view classifier: predict was called before training");
  if (descriptors.cols() != mean_.size()) {
    throw Error("view classifier: descriptors have " + std::to_string(descriptors.cols()) +
                " columns, the classifier was trained on " + std::to_string(mean_.size()));
  }
  if (!descriptors.allFinite()) {
    throw Error("view classifier: the descriptors to classify contain NaN or infinite values");
  }
  const Eigen::MatrixXf standardised = standardise(descriptors);
  if (clusters() == 1) return regressions_.front().predictProbabilities(standardised);

  const Eigen::VectorXi cluster = nearestCentroids(centroids_, standardised);
  Eigen::MatrixXf probabilities(descriptors.rows(), num_views_);
  for (int c = 0; c < clusters(); ++c) {
    std::vector<Eigen::Index> rows;
    for (Eigen::Index i = 0; i < cluster.size(); ++i) {
      if (cluster(i) == c) rows.push_back(i);
    }
    if (rows.empty()) continue;
    Eigen::MatrixXf X(static_cast<Eigen::Index>(rows.size()), descriptors.cols());
    for (std::size_t r = 0; r < rows.size(); ++r)
      X.row(static_cast<Eigen::Index>(r)) = standardised.row(rows[r]);
    const Eigen::MatrixXf P = regressions_[static_cast<std::size_t>(c)].predictProbabilities(X);
    for (std::size_t r = 0; r < rows.size(); ++r)
      probabilities.row(rows[r]) = P.row(static_cast<Eigen::Index>(r));
  }
  return probabilities;
}

HeldOutMetrics evaluateClassifier(const ViewClassifier& classifier,
                                  const Eigen::MatrixXf& descriptors,
                                  const Eigen::VectorXi& labels) {
  if (!classifier.trained())
    throw Error("view classifier: cannot evaluate an untrained classifier");
  checkLabelled(descriptors, labels, classifier.numViews(), "held-out");
  const Eigen::MatrixXf P = classifier.predict(descriptors);
  std::size_t correct = 0;
  for (Eigen::Index i = 0; i < P.rows(); ++i) {
    Eigen::Index best;
    P.row(i).maxCoeff(&best);
    if (best == labels(i)) ++correct;
  }
  HeldOutMetrics metrics;
  metrics.features = static_cast<std::size_t>(P.rows());
  metrics.accuracy = static_cast<double>(correct) / static_cast<double>(metrics.features);
  metrics.log_loss = featureKlDivergences(P, labels).cast<double>().mean();
  return metrics;
}

}  // namespace vdc
