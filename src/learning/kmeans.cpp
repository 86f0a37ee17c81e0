#include "view_direction_classification/learning/kmeans.h"

#include <algorithm>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

// A uniform number in [0, 1) from the raw generator output: std::uniform_real_distribution is
// implementation-defined, and the seeding must give the same clusters with every standard library.
double uniform01(std::mt19937& rng) { return static_cast<double>(rng()) / 4294967296.0; }

double squaredDistance(const Eigen::MatrixXf& a, Eigen::Index i, const Eigen::MatrixXf& b,
                       Eigen::Index j) {
  return (a.row(i).cast<double>() - b.row(j).cast<double>()).squaredNorm();
}

// Nearest centroid of each point and its squared distance.
void assign(const Eigen::MatrixXf& centroids, const Eigen::MatrixXf& points,
            Eigen::VectorXi* assignment, Eigen::VectorXd* distance) {
  const Eigen::Index n = points.rows();
  assignment->resize(n);
  if (distance) distance->resize(n);
#pragma omp parallel for schedule(static)
  for (Eigen::Index i = 0; i < n; ++i) {
    double best = std::numeric_limits<double>::infinity();
    int best_index = 0;
    for (Eigen::Index c = 0; c < centroids.rows(); ++c) {
      const double d2 = squaredDistance(points, i, centroids, c);
      if (d2 < best) {
        best = d2;
        best_index = static_cast<int>(c);
      }
    }
    (*assignment)(i) = best_index;
    if (distance) (*distance)(i) = best;
  }
}

// k-means++ (Arthur and Vassilvitskii 2007): each next seed is drawn with probability
// proportional to its squared distance to the nearest seed chosen so far.
Eigen::MatrixXf seedPlusPlus(const Eigen::MatrixXf& points, int k, std::mt19937& rng) {
  const Eigen::Index n = points.rows();
  Eigen::MatrixXf centroids(k, points.cols());
  Eigen::Index first = static_cast<Eigen::Index>(uniform01(rng) * static_cast<double>(n));
  centroids.row(0) = points.row(first);
  Eigen::VectorXd nearest(n);
  for (Eigen::Index i = 0; i < n; ++i) nearest(i) = squaredDistance(points, i, centroids, 0);
  for (int c = 1; c < k; ++c) {
    const double total = nearest.sum();
    Eigen::Index chosen = n - 1;
    if (total > 0.0) {
      const double target = uniform01(rng) * total;
      double cumulative = 0.0;
      for (Eigen::Index i = 0; i < n; ++i) {
        cumulative += nearest(i);
        if (cumulative > target && nearest(i) > 0.0) {
          chosen = i;
          break;
        }
      }
    } else {
      // Every point coincides with a seed: any point will do (duplicates are harmless).
      chosen = static_cast<Eigen::Index>(uniform01(rng) * static_cast<double>(n));
    }
    centroids.row(c) = points.row(chosen);
    for (Eigen::Index i = 0; i < n; ++i) {
      nearest(i) = std::min(nearest(i), squaredDistance(points, i, centroids, c));
    }
  }
  return centroids;
}

}  // namespace

Eigen::MatrixXf kMeans(const Eigen::MatrixXf& points, int k, const KMeansOptions& options) {
  if (k < 1)
    throw Error("k-means: the number of clusters must be at least 1, got " + std::to_string(k));
  if (points.rows() < k) {
    throw Error("k-means: " + std::to_string(k) + " clusters requested but there are only " +
                std::to_string(points.rows()) + " points");
  }
  if (!points.allFinite()) throw Error("k-means: the points contain NaN or infinite values");
  if (options.max_iterations < 0) {
    throw Error("k-means: max_iterations must be >= 0, got " +
                std::to_string(options.max_iterations));
  }

  std::mt19937 rng(options.seed);
  Eigen::MatrixXf centroids = seedPlusPlus(points, k, rng);
  const Eigen::Index n = points.rows();
  Eigen::VectorXi assignment = Eigen::VectorXi::Constant(n, -1);
  for (int iteration = 0; iteration < options.max_iterations; ++iteration) {
    Eigen::VectorXi next;
    Eigen::VectorXd distance;
    assign(centroids, points, &next, &distance);
    const bool changed = (next.array() != assignment.array()).any();
    assignment = next;
    if (!changed) break;

    Eigen::MatrixXd sums = Eigen::MatrixXd::Zero(k, points.cols());
    Eigen::VectorXi counts = Eigen::VectorXi::Zero(k);
    for (Eigen::Index i = 0; i < n; ++i) {
      sums.row(assignment(i)) += points.row(i).cast<double>();
      ++counts(assignment(i));
    }
    for (int c = 0; c < k; ++c) {
      if (counts(c) > 0) {
        centroids.row(c) = (sums.row(c) / counts(c)).cast<float>();
      } else {
        // Empty cluster: move it to the worst-served point, which takes that point over.
        Eigen::Index farthest = 0;
        distance.maxCoeff(&farthest);
        centroids.row(c) = points.row(farthest);
        distance(farthest) = 0.0;
        assignment(farthest) = c;
      }
    }
  }
  return centroids;
}

Eigen::VectorXi nearestCentroids(const Eigen::MatrixXf& centroids, const Eigen::MatrixXf& points) {
  if (centroids.rows() < 1) throw Error("k-means: there are no centroids to assign points to");
  if (centroids.cols() != points.cols()) {
    throw Error("k-means: points have " + std::to_string(points.cols()) +
                " columns but the centroids " + std::to_string(centroids.cols()));
  }
  Eigen::VectorXi assignment;
  assign(centroids, points, &assignment, nullptr);
  return assignment;
}

}  // namespace vdc
