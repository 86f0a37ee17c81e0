#include "fit_covariance.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <vector>

namespace vdc {

namespace {

// The point-to-plane matches of a fitted pose, in the object frame.
struct Matches {
  std::vector<Eigen::Vector3d> points, normals;  // observed point, model normal at its match
  double squared_residuals = 0.0;
  int count() const { return static_cast<int>(points.size()); }
  // Six of the degrees of freedom are the pose's: the residual variance's denominator counts
  // them.
  double residualVariance() const { return squared_residuals / (count() - 6); }
};

Matches matchesOf(const ModelSurface& surface, const pcl::PointCloud<pcl::PointXYZ>& points_world,
                  const Eigen::Isometry3d& world_from_object, double max_distance) {
  const Eigen::Isometry3f object_from_world = world_from_object.inverse().cast<float>();
  const float max_squared = static_cast<float>(max_distance * max_distance);
  const std::vector<Eigen::Vector3f> queries = objectFramePoints(points_world, object_from_world);
  std::vector<int> indices;
  std::vector<float> squared;
  surface.nearest().search(queries, &indices, &squared, max_distance);
  Matches matches;
  for (std::size_t i = 0; i < queries.size(); ++i) {
    if (indices[i] < 0 || squared[i] > max_squared) continue;
    const auto& sample = (*surface.cloud())[indices[i]];
    const Eigen::Vector3d n = sample.getNormalVector3fMap().cast<double>();
    const double residual = n.dot((queries[i] - sample.getVector3fMap()).cast<double>());
    matches.points.push_back(queries[i].cast<double>());
    matches.normals.push_back(n);
    matches.squared_residuals += residual * residual;
  }
  return matches;
}

// The covariance whose inverse is `information` [1 / variance], each principal variance clamped
// to [min_sigma^2, max_sigma^2] (a direction without information gets max_sigma^2).
Eigen::Matrix3d clampedCovariance(const Eigen::Matrix3d& information, double min_sigma,
                                  double max_sigma) {
  const double min_variance = min_sigma * min_sigma, max_variance = max_sigma * max_sigma;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(information);
  Eigen::Vector3d variances;
  for (int i = 0; i < 3; ++i) {
    const double eigenvalue = solver.eigenvalues()(i);
    const double variance = eigenvalue > 0.0 ? 1.0 / eigenvalue : max_variance;
    variances(i) = std::clamp(variance, min_variance, max_variance);
  }
  return solver.eigenvectors() * variances.asDiagonal() * solver.eigenvectors().transpose();
}

// The translation's covariance [m^2, fixed frame] from the matches.
Eigen::Matrix3d translationFrom(const Matches& matches, const Eigen::Isometry3d& world_from_object,
                                double min_sigma, double max_sigma) {
  Eigen::Matrix3d information = Eigen::Matrix3d::Zero();  // sum n n^T, object frame
  for (const Eigen::Vector3d& n : matches.normals) information += n * n.transpose();
  const Eigen::Matrix3d object_frame = clampedCovariance(
      information / std::max(matches.residualVariance(), 1e-300), min_sigma, max_sigma);
  const Eigen::Matrix3d rotation = world_from_object.linear();
  return rotation * object_frame * rotation.transpose();
}

// The turn's covariance [rad^2, object frame] from the matches.
Eigen::Matrix3d rotationFrom(const Matches& matches, double min_sigma, double max_sigma,
                             double min_shift_sigma) {
  // Gauss-Newton information of (turn, shift): each match's residual changes by
  // -(x - c) x n . turn + n . shift. About the matches' centroid c the two blocks decouple
  // better; the turn's marginal does not depend on c.
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : matches.points) centroid += p;
  centroid /= matches.count();
  double squared_lever = 0.0;
  for (const Eigen::Vector3d& p : matches.points) squared_lever += (p - centroid).squaredNorm();
  const double lever = std::sqrt(squared_lever / matches.count());
  Eigen::Matrix<double, 6, 6> information = Eigen::Matrix<double, 6, 6>::Zero();
  for (int i = 0; i < matches.count(); ++i) {
    Eigen::Matrix<double, 6, 1> jacobian;
    jacobian << (matches.points[i] - centroid).cross(matches.normals[i]), matches.normals[i];
    information += jacobian * jacobian.transpose();
  }
  // The turn's marginal information: the Schur complement of the shift block (a pseudo-inverse
  // where the matched surface leaves a shift free, a cylinder's slide along its axis).
  const Eigen::Matrix3d shift_shift = information.bottomRightCorner<3, 3>();
  const Eigen::Matrix3d turn_shift = information.topRightCorner<3, 3>();
  const Eigen::Matrix3d shift_inverse =
      shift_shift.completeOrthogonalDecomposition().pseudoInverse();
  const Eigen::Matrix3d turn_information =
      information.topLeftCorner<3, 3>() - turn_shift * shift_inverse * turn_shift.transpose();
  // The shift's floor over the matched points' lever: a patch turns more for the same
  // millimetre than a whole view does.
  const double floor = std::min(max_sigma, std::max(min_sigma, min_shift_sigma / lever));
  return clampedCovariance(turn_information / std::max(matches.residualVariance(), 1e-300), floor,
                           max_sigma);
}

}  // namespace

FitCovariance fitCovariance(const ModelSurface& surface,
                            const pcl::PointCloud<pcl::PointXYZ>& points_world,
                            const Eigen::Isometry3d& world_from_object, double max_distance,
                            const CovarianceBounds& bounds) {
  const Matches matches = matchesOf(surface, points_world, world_from_object, max_distance);
  if (matches.count() < 7) {
    return {bounds.max_shift_sigma * bounds.max_shift_sigma * Eigen::Matrix3d::Identity(),
            bounds.max_turn_sigma * bounds.max_turn_sigma * Eigen::Matrix3d::Identity()};
  }
  return {
      translationFrom(matches, world_from_object, bounds.min_shift_sigma, bounds.max_shift_sigma),
      rotationFrom(matches, bounds.min_turn_sigma, bounds.max_turn_sigma, bounds.min_shift_sigma)};
}

}  // namespace vdc
