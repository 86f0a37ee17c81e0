#pragma once

#include <Eigen/Core>

#include <vector>

namespace vdc {

// Feature selection of doc/method.md section 5, the one used by training, scoring and the online
// estimator alike: a cloud's features are ranked by the entropy of their view distribution
// p(D | f) and the most certain ones are summed.

// Shannon entropy (nats) of each row of an n x M probability matrix, with 0 ln 0 = 0.
// Throws vdc::Error for a negative or non-finite probability.
Eigen::VectorXf rowEntropies(const Eigen::MatrixXf& probabilities);

// Indices of the min(count, n) rows of lowest entropy, by ascending entropy, ties by lower index.
// Throws vdc::Error if count < 1.
std::vector<int> mostCertainFeatures(const Eigen::MatrixXf& probabilities, int count);

// p_sum: the sum of the `n_feat` most certain rows, normalised to sum 1 (length M).
// Throws vdc::Error for zero rows, n_feat < 1, or rows that sum to zero.
Eigen::VectorXd summedDistribution(const Eigen::MatrixXf& probabilities, int n_feat = 50);

}  // namespace vdc
