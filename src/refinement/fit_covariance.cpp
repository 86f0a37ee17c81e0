#include "fit_covariance.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <vector>

namespace vdc {

Eigen::Matrix3d translationCovariance(const ModelSurface& surface,
                                      const pcl::PointCloud<pcl::PointXYZ>& points_world,
                                      const Eigen::Isometry3d& world_from_object,
                                      double max_distance, double min_sigma, double max_sigma) {
  const double min_variance = min_sigma * min_sigma, max_variance = max_sigma * max_sigma;
  const Eigen::Isometry3f object_from_world = world_from_object.inverse().cast<float>();
  const float max_squared = static_cast<float>(max_distance * max_distance);
  Eigen::Matrix3d information = Eigen::Matrix3d::Zero();  // sum n n^T, object frame
  double squared_residuals = 0.0;
  int matches = 0;
  const std::vector<Eigen::Vector3f> queries = objectFramePoints(points_world, object_from_world);
  std::vector<int> indices;
  std::vector<float> squared;
  surface.nearest().search(queries, &indices, &squared);
  for (std::size_t i = 0; i < queries.size(); ++i) {
    if (indices[i] < 0 || squared[i] > max_squared) continue;
    const auto& sample = (*surface.cloud())[indices[i]];
    const Eigen::Vector3d n = sample.getNormalVector3fMap().cast<double>();
    const double residual = n.dot((queries[i] - sample.getVector3fMap()).cast<double>());
    information += n * n.transpose();
    squared_residuals += residual * residual;
    ++matches;
  }
  if (matches < 6) return max_variance * Eigen::Matrix3d::Identity();
  // Three of the six degrees of freedom are the translation's: the residual variance's
  // denominator counts all six.
  const double residual_variance = squared_residuals / (matches - 6);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(information);
  Eigen::Vector3d variances;
  for (int i = 0; i < 3; ++i) {
    const double eigenvalue = solver.eigenvalues()(i);
    const double variance = eigenvalue > 0.0 ? residual_variance / eigenvalue : max_variance;
    variances(i) = std::clamp(variance, min_variance, max_variance);
  }
  const Eigen::Matrix3d object_frame =
      solver.eigenvectors() * variances.asDiagonal() * solver.eigenvectors().transpose();
  const Eigen::Matrix3d rotation = world_from_object.linear();
  return rotation * object_frame * rotation.transpose();
}

}  // namespace vdc
