#include "view_direction_classification/geometry/point_spread.h"

#include <pcl/common/centroid.h>

#include <Eigen/Eigenvalues>

namespace vdc {
namespace {

// Fewer points than this make no fit worth its RANSAC (and three are its minimum sample).
constexpr std::size_t kMinPoints = 10;

}  // namespace

bool spreadsInTwoDirections(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                            const pcl::Indices& indices, double min_spread) {
  if ((indices.empty() ? cloud.size() : indices.size()) < kMinPoints) return false;
  Eigen::Matrix3f covariance;
  Eigen::Vector4f centroid;
  const unsigned int used =
      indices.empty() ? pcl::computeMeanAndCovarianceMatrix(cloud, covariance, centroid)
                      : pcl::computeMeanAndCovarianceMatrix(cloud, indices, covariance, centroid);
  if (used < kMinPoints || !covariance.allFinite()) return false;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3f> solver(covariance, Eigen::EigenvaluesOnly);
  // Ascending: the middle one is the spread across the points' main direction.
  return solver.eigenvalues()(1) >= static_cast<float>(min_spread * min_spread);
}

}  // namespace vdc
