#include "view_direction_classification/learning/feature_selection.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "view_direction_classification/common/error.h"

namespace vdc {

Eigen::VectorXf rowEntropies(const Eigen::MatrixXf& probabilities) {
  if (!probabilities.allFinite() || (probabilities.array() < 0.0f).any()) {
    throw Error("feature selection: the view probabilities contain a negative or non-finite value");
  }
  Eigen::VectorXf entropies(probabilities.rows());
  for (Eigen::Index i = 0; i < probabilities.rows(); ++i) {
    double h = 0.0;
    for (Eigen::Index m = 0; m < probabilities.cols(); ++m) {
      const double p = probabilities(i, m);
      if (p > 0.0) h -= p * std::log(p);
    }
    entropies(i) = static_cast<float>(h);
  }
  return entropies;
}

std::vector<int> mostCertainFeatures(const Eigen::MatrixXf& probabilities, int count) {
  if (count < 1) {
    throw Error("feature selection: the number of features to keep must be at least 1, got " +
                std::to_string(count));
  }
  const Eigen::VectorXf entropies = rowEntropies(probabilities);
  std::vector<int> order(static_cast<std::size_t>(entropies.size()));
  std::iota(order.begin(), order.end(), 0);
  const std::size_t keep = std::min(order.size(), static_cast<std::size_t>(count));
  // (entropy, index) is a strict total order, so partial_sort's result is unique.
  std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(keep), order.end(),
                    [&](int a, int b) {
                      return entropies(a) < entropies(b) || (entropies(a) == entropies(b) && a < b);
                    });
  order.resize(keep);
  return order;
}

Eigen::VectorXd summedDistribution(const Eigen::MatrixXf& probabilities, int n_feat) {
  if (probabilities.rows() == 0) {
    throw Error("feature selection: the cloud has no features, so it has no summed distribution");
  }
  if (n_feat < 1) {
    throw Error("feature selection: n_feat must be at least 1, got " + std::to_string(n_feat));
  }
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(probabilities.cols());
  for (int row : mostCertainFeatures(probabilities, n_feat)) {
    sum += probabilities.row(row).transpose().cast<double>();
  }
  const double total = sum.sum();
  if (!(total > 0.0)) {
    throw Error("feature selection: the selected view distributions sum to zero");
  }
  return sum / total;
}

}  // namespace vdc
