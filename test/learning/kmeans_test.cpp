#include "view_direction_classification/learning/kmeans.h"

#include <gtest/gtest.h>

#include <random>
#include <set>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

Eigen::MatrixXf blobs(const Eigen::MatrixXf& centres, int per_blob, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<float> noise(0.0f, 0.3f);
  Eigen::MatrixXf points(centres.rows() * per_blob, centres.cols());
  for (Eigen::Index c = 0; c < centres.rows(); ++c) {
    for (int k = 0; k < per_blob; ++k) {
      for (Eigen::Index j = 0; j < centres.cols(); ++j) {
        points(c * per_blob + k, j) = centres(c, j) + noise(rng);
      }
    }
  }
  return points;
}

TEST(KMeans, FindsWellSeparatedClusters) {
  Eigen::MatrixXf centres(4, 3);
  centres << 0, 0, 0, 10, 0, 0, 0, 10, 0, 0, 0, 10;
  const Eigen::MatrixXf points = blobs(centres, 40, 2);
  const Eigen::MatrixXf found = kMeans(points, 4);
  ASSERT_EQ(found.rows(), 4);
  ASSERT_EQ(found.cols(), 3);
  std::set<int> matched;
  for (Eigen::Index c = 0; c < centres.rows(); ++c) {
    Eigen::Index nearest;
    (found.rowwise() - centres.row(c)).rowwise().norm().minCoeff(&nearest);
    EXPECT_LT((found.row(nearest) - centres.row(c)).norm(), 0.2f) << "centre " << c;
    matched.insert(static_cast<int>(nearest));
  }
  EXPECT_EQ(matched.size(), 4u);  // one centroid per blob
}

TEST(KMeans, AssignsEachPointToItsNearestCentroid) {
  Eigen::MatrixXf centroids(2, 1);
  centroids << 0, 10;
  Eigen::MatrixXf points(4, 1);
  points << -1, 4.9f, 5.1f, 20;
  const Eigen::VectorXi assignment = nearestCentroids(centroids, points);
  EXPECT_EQ(assignment(0), 0);
  EXPECT_EQ(assignment(1), 0);
  EXPECT_EQ(assignment(2), 1);
  EXPECT_EQ(assignment(3), 1);
}

TEST(KMeans, IsDeterministicForASeed) {
  Eigen::MatrixXf centres(3, 2);
  centres << 0, 0, 3, 0, 0, 3;
  const Eigen::MatrixXf points = blobs(centres, 30, 4);
  KMeansOptions options;
  options.seed = 9;
  EXPECT_EQ(kMeans(points, 3, options), kMeans(points, 3, options));
}

TEST(KMeans, HandlesDuplicatePointsWithoutEmptyClusters) {
  Eigen::MatrixXf points = Eigen::MatrixXf::Ones(10, 2);
  points.row(9) << 5, 5;
  const Eigen::MatrixXf found = kMeans(points, 3);
  EXPECT_TRUE(found.allFinite());
  const Eigen::VectorXi assignment = nearestCentroids(found, points);
  EXPECT_NE(assignment(9), assignment(0));
}

TEST(KMeans, RefusesMoreClustersThanPointsAndNonFiniteInput) {
  EXPECT_THROW(kMeans(Eigen::MatrixXf::Zero(2, 2), 3), Error);
  EXPECT_THROW(kMeans(Eigen::MatrixXf::Zero(2, 2), 0), Error);
  Eigen::MatrixXf points = Eigen::MatrixXf::Zero(3, 2);
  points(1, 1) = std::nanf("");
  EXPECT_THROW(kMeans(points, 2), Error);
  EXPECT_THROW(nearestCentroids(Eigen::MatrixXf::Zero(2, 3), points), Error);
}

}  // namespace
}  // namespace vdc
