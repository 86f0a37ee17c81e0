#include "view_direction_classification/learning/logistic_regression.h"

#include <LBFGS.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/parallel_for.h"

namespace vdc {
namespace {

// Samples are processed in blocks: each block's contribution is computed by one thread and the
// blocks are summed in a fixed order afterwards, so the result is bit-identical for any number
// of threads (a critical-section reduction would make training depend on thread timing).
constexpr Eigen::Index kBlockRows = 2048;

void checkSamples(const Eigen::MatrixXf& X, const Eigen::VectorXi& labels, int num_classes) {
  if (X.rows() == 0) {
    throw Error("logistic regression: there are no training samples (0 rows)");
  }
  if (labels.size() != X.rows()) {
    throw Error("logistic regression: " + std::to_string(X.rows()) + " samples but " +
                std::to_string(labels.size()) + " labels");
  }
  if (num_classes < 1) {
    throw Error("logistic regression: the number of classes must be at least 1, got " +
                std::to_string(num_classes));
  }
  for (Eigen::Index i = 0; i < labels.size(); ++i) {
    if (labels(i) < 0 || labels(i) >= num_classes) {
      throw Error("logistic regression: label " + std::to_string(labels(i)) + " of sample " +
                  std::to_string(i) + " is outside [0, " + std::to_string(num_classes) + ")");
    }
  }
}

// Turns each row of `scores` into log-probabilities (log-sum-exp, so no overflow for any score).
void logSoftmaxRows(Eigen::MatrixXd& scores) {
  for (Eigen::Index r = 0; r < scores.rows(); ++r) {
    const double top = scores.row(r).maxCoeff();
    const double log_sum = top + std::log((scores.row(r).array() - top).exp().sum());
    scores.row(r).array() -= log_sum;
  }
}

// Adapts the loss to LBFGS++'s f(x, grad) interface. It also remembers the best point it was
// asked about: LBFGS++ throws when a line search cannot make progress (typically at numerical
// convergence), and then the best point seen is the answer.
class Objective {
 public:
  Objective(const Eigen::MatrixXf& X, const Eigen::VectorXi& labels, double l2, int num_classes)
      : X_(X), labels_(labels), l2_(l2), rows_(X.cols() + 1), cols_(num_classes) {}

  double operator()(const Eigen::VectorXd& w, Eigen::VectorXd& grad) {
    const Eigen::MatrixXd W = Eigen::Map<const Eigen::MatrixXd>(w.data(), rows_, cols_);
    Eigen::MatrixXd G;
    const double f = MultinomialLogisticRegression::loss(W, X_, labels_, l2_, &G);
    grad = Eigen::Map<const Eigen::VectorXd>(G.data(), G.size());
    if (std::isfinite(f) && f < best_value_) {
      best_value_ = f;
      best_point_ = w;
    }
    return f;
  }

  double bestValue() const { return best_value_; }
  const Eigen::VectorXd& bestPoint() const { return best_point_; }

 private:
  const Eigen::MatrixXf& X_;
  const Eigen::VectorXi& labels_;
  double l2_;
  Eigen::Index rows_, cols_;
  double best_value_ = std::numeric_limits<double>::infinity();
  Eigen::VectorXd best_point_;
};

}  // namespace

MultinomialLogisticRegression::MultinomialLogisticRegression(Eigen::MatrixXd weights) {
  setWeights(std::move(weights));
}

double MultinomialLogisticRegression::loss(const Eigen::MatrixXd& W, const Eigen::MatrixXf& X,
                                           const Eigen::VectorXi& labels, double l2,
                                           Eigen::MatrixXd* gradient) {
  checkSamples(X, labels, static_cast<int>(W.cols()));
  const Eigen::Index n = X.rows();
  const Eigen::Index d = X.cols();
  if (W.rows() != d + 1) {
    throw Error("logistic regression: weights have " + std::to_string(W.rows()) +
                " rows, expected " + std::to_string(d + 1) + " (inputs + bias)");
  }
  const Eigen::Index classes = W.cols();
  const Eigen::Index blocks = (n + kBlockRows - 1) / kBlockRows;
  std::vector<double> block_nll(static_cast<std::size_t>(blocks), 0.0);
  std::vector<Eigen::MatrixXd> block_gradient(gradient ? static_cast<std::size_t>(blocks) : 0);

#pragma omp parallel for schedule(dynamic)
  for (Eigen::Index b = 0; b < blocks; ++b) {
    const Eigen::Index start = b * kBlockRows;
    const Eigen::Index rows = std::min(kBlockRows, n - start);
    const Eigen::MatrixXd Xb = X.middleRows(start, rows).cast<double>();
    Eigen::MatrixXd scores = Xb * W.topRows(d);
    scores.rowwise() += W.row(d);
    logSoftmaxRows(scores);
    double nll = 0.0;
    for (Eigen::Index r = 0; r < rows; ++r) nll -= scores(r, labels(start + r));
    block_nll[static_cast<std::size_t>(b)] = nll;
    if (gradient) {
      // d(-log p_y)/d(score) = p - onehot(y)
      Eigen::MatrixXd residual = scores.array().exp();
      for (Eigen::Index r = 0; r < rows; ++r) residual(r, labels(start + r)) -= 1.0;
      Eigen::MatrixXd& g = block_gradient[static_cast<std::size_t>(b)];
      g.resize(d + 1, classes);
      g.topRows(d).noalias() = Xb.transpose() * residual;
      g.row(d) = residual.colwise().sum();
    }
  }

  double nll = 0.0;
  for (double v : block_nll) nll += v;
  const double inv_n = 1.0 / static_cast<double>(n);
  const double value = nll * inv_n + 0.5 * l2 * W.topRows(d).squaredNorm();
  if (gradient) {
    gradient->setZero(d + 1, classes);
    for (const auto& g : block_gradient) *gradient += g;
    *gradient *= inv_n;
    gradient->topRows(d) += l2 * W.topRows(d);
  }
  return value;
}

void MultinomialLogisticRegression::fit(const Eigen::MatrixXf& X, const Eigen::VectorXi& labels,
                                        int num_classes, const Options& options) {
  checkSamples(X, labels, num_classes);
  if (!X.allFinite()) {
    throw Error("logistic regression: the training samples contain NaN or infinite values");
  }
  if (!(options.l2 >= 0.0) || !std::isfinite(options.l2)) {
    throw Error("logistic regression: l2 must be a finite value >= 0, got " +
                std::to_string(options.l2));
  }
  if (options.max_iterations < 1) {
    throw Error("logistic regression: max_iterations must be at least 1, got " +
                std::to_string(options.max_iterations));
  }
  if (!(options.epsilon > 0.0)) {
    throw Error("logistic regression: epsilon must be positive, got " +
                std::to_string(options.epsilon));
  }

  LBFGSpp::LBFGSParam<double> param;
  param.epsilon = options.epsilon;
  param.epsilon_rel = options.epsilon;
  param.max_iterations = options.max_iterations;
  // Also stop when the loss stagnates: with empty classes the gradient of their bias only decays
  // slowly towards 0 and would otherwise use up every iteration.
  param.past = 3;
  param.delta = 1e-10;
  param.linesearch = LBFGSpp::LBFGS_LINESEARCH_BACKTRACKING_STRONG_WOLFE;
  LBFGSpp::LBFGSSolver<double, LBFGSpp::LineSearchNocedalWright> solver(param);

  const Eigen::Index size = (X.cols() + 1) * num_classes;
  Objective objective(X, labels, options.l2, num_classes);
  Eigen::VectorXd w = Eigen::VectorXd::Zero(size);
  double value = 0.0;
  iterations_ = 0;
  try {
    iterations_ = solver.minimize(objective, w, value);
  } catch (const std::runtime_error&) {
    // Line search could not decrease the loss any further: keep the best point seen.
    iterations_ = param.max_iterations;
  } catch (const std::logic_error&) {
    iterations_ = param.max_iterations;
  }
  if (!std::isfinite(objective.bestValue())) {
    throw Error("logistic regression: training diverged (the loss is not finite)");
  }
  weights_ =
      Eigen::Map<const Eigen::MatrixXd>(objective.bestPoint().data(), X.cols() + 1, num_classes);
}

Eigen::MatrixXf MultinomialLogisticRegression::predictProbabilities(
    const Eigen::MatrixXf& X) const {
  if (!trained()) {
    throw Error("logistic regression: predict was called before the model was trained");
  }
  const Eigen::Index d = inputDimension();
  if (X.cols() != d) {
    throw Error("logistic regression: samples have " + std::to_string(X.cols()) +
                " columns, the model expects " + std::to_string(d));
  }
  if (!X.allFinite()) {
    throw Error("logistic regression: the samples to classify contain NaN or infinite values");
  }
  const Eigen::Index n = X.rows();
  Eigen::MatrixXf probabilities(n, weights_.cols());
  const Eigen::Index blocks = (n + kBlockRows - 1) / kBlockRows;
  // On plain threads, not OpenMP: this runs on the estimator's path (common/parallel_for.h). A
  // lazy (coefficient-wise) product: Eigen's blocked product would start OpenMP threads of its
  // own inside each of these, and the inner dimension (the descriptor's 33 bins) is small.
  parallelFor(static_cast<std::size_t>(blocks), hardwareThreads(), [&](int, std::size_t b) {
    const Eigen::Index start = static_cast<Eigen::Index>(b) * kBlockRows;
    const Eigen::Index rows = std::min(kBlockRows, n - start);
    Eigen::MatrixXd scores =
        X.middleRows(start, rows).cast<double>().lazyProduct(weights_.topRows(d));
    scores.rowwise() += weights_.row(d);
    logSoftmaxRows(scores);
    probabilities.middleRows(start, rows) = scores.array().exp().cast<float>().matrix();
  });
  return probabilities;
}

void MultinomialLogisticRegression::setWeights(Eigen::MatrixXd W) {
  if (W.rows() < 1 || W.cols() < 1) {
    throw Error(
        "logistic regression: weights must have at least one row (the bias) and one "
        "class column, got " +
        std::to_string(W.rows()) + " x " + std::to_string(W.cols()));
  }
  if (!W.allFinite()) {
    throw Error("logistic regression: the weights contain NaN or infinite values");
  }
  weights_ = std::move(W);
  iterations_ = 0;
}

}  // namespace vdc
