#include "candidate_shape.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <limits>

namespace vdc::scene {

void describeShape(const pcl::PointCloud<pcl::PointXYZ>& cloud, SceneCandidate* candidate) {
  const double n = static_cast<double>(candidate->indices.size());
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const int i : candidate->indices) mean += cloud[i].getVector3fMap().cast<double>();
  mean /= n;
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const int i : candidate->indices) {
    const Eigen::Vector3d d = cloud[i].getVector3fMap().cast<double>() - mean;
    scatter += d * d.transpose();
  }
  // Eigenvalues come ascending: reverse the axes so that the largest spread comes first, and
  // keep a right-handed frame.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(scatter / n);
  Eigen::Matrix3d axes = solver.eigenvectors().rowwise().reverse();
  axes.col(2) = axes.col(0).cross(axes.col(1));
  Eigen::Vector3d low = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d high = -low;
  for (const int i : candidate->indices) {
    const Eigen::Vector3d projected =
        axes.transpose() * (cloud[i].getVector3fMap().cast<double>() - mean);
    low = low.cwiseMin(projected);
    high = high.cwiseMax(projected);
  }
  // The largest variance is almost always the largest side, but not always (a few outliers):
  // order the sides themselves.
  const Eigen::Vector3d sides = high - low;
  int order[3] = {0, 1, 2};
  std::sort(order, order + 3, [&](int a, int b) { return sides(a) > sides(b); });
  candidate->centroid = mean;
  for (int k = 0; k < 3; ++k) {
    candidate->extent(k) = sides(order[k]);
    candidate->axes.col(k) = axes.col(order[k]);
  }
  candidate->axes.col(2) = candidate->axes.col(0).cross(candidate->axes.col(1));
}

}  // namespace vdc::scene
