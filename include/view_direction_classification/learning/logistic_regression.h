#pragma once

#include <Eigen/Core>

namespace vdc {

// Multinomial logistic regression (softmax regression) with an L2 penalty on the weights, the
// classifier of doc/method.md section 4. Trained with L-BFGS (LBFGS++) in double precision; the loss
// and its gradient are evaluated in parallel over blocks of samples (OpenMP).
class MultinomialLogisticRegression {
 public:
  struct Options {
    double l2 = 1e-4;          // penalty l2/2 |W|^2 on the weights, not on the bias
    int max_iterations = 300;  // L-BFGS iterations
    double epsilon = 1e-6;     // stop when |gradient| < epsilon * max(1, |W|)
  };

  MultinomialLogisticRegression() = default;
  // A trained model from stored weights ((d+1) x classes, last row = bias); see setWeights.
  explicit MultinomialLogisticRegression(Eigen::MatrixXd weights);

  // X: n x d (already standardised), labels in [0, num_classes). Classes without samples are
  // allowed (their probability stays low). Throws vdc::Error for n == 0, a label out of range,
  // mismatched sizes, non-finite X or invalid options.
  void fit(const Eigen::MatrixXf& X, const Eigen::VectorXi& labels, int num_classes,
           const Options& options);

  // n x classes, each row sums to 1. Throws vdc::Error if untrained or X has the wrong width.
  Eigen::MatrixXf predictProbabilities(const Eigen::MatrixXf& X) const;

  // Mean negative log-likelihood + l2/2 |W without the bias row|^2, and (if `gradient` is not
  // null) its gradient, of the same shape as W. W is (d+1) x classes, the last row the bias.
  // Public so the gradient can be tested against finite differences.
  static double loss(const Eigen::MatrixXd& W, const Eigen::MatrixXf& X,
                     const Eigen::VectorXi& labels, double l2, Eigen::MatrixXd* gradient);

  const Eigen::MatrixXd& weights() const { return weights_; }
  // Throws vdc::Error if W has no row (no bias), no column or a non-finite entry.
  void setWeights(Eigen::MatrixXd W);

  bool trained() const { return weights_.size() > 0; }
  int numClasses() const { return static_cast<int>(weights_.cols()); }
  int inputDimension() const { return static_cast<int>(weights_.rows()) - 1; }
  // L-BFGS iterations of the last fit (0 if loaded from weights).
  int iterations() const { return iterations_; }

 private:
  Eigen::MatrixXd weights_;
  int iterations_ = 0;
};

}  // namespace vdc
