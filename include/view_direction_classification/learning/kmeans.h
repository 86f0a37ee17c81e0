#pragma once

#include <Eigen/Core>

#include <cstdint>

namespace vdc {

struct KMeansOptions {
  int max_iterations = 100;  // Lloyd iterations; stops earlier when no assignment changes
  std::uint32_t seed = 1;    // k-means++ seeding
};

// K-means clustering of the rows of `points` (n x d): k-means++ seeding with a fixed seed, then
// Lloyd iterations. Returns the centroids, k x d. A cluster that loses all its points is re-seeded
// with the point farthest from its centroid, so every centroid has at least one point.
// Deterministic for a seed. Throws vdc::Error if k < 1, k > n or a point is not finite.
Eigen::MatrixXf kMeans(const Eigen::MatrixXf& points, int k, const KMeansOptions& options = {});

// Index of the centroid nearest to each row of `points` (ties: the lower index).
// Throws vdc::Error if there is no centroid or the widths differ.
Eigen::VectorXi nearestCentroids(const Eigen::MatrixXf& centroids, const Eigen::MatrixXf& points);

}  // namespace vdc
