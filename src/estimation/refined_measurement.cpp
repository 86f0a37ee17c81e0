#include "view_direction_classification/estimation/refined_measurement.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/quaternion.h"

namespace vdc {

namespace {

// The exponent of a pose's component. A small turn t of the pose (q (1, t / 2), object frame)
// has density exp(-t^T L t / 2) for the information L: the inverse of the fit's rotation
// covariance, or c / 2 I for the fixed concentration c when the pose has none;
// with V = [q (0, e_x), q (0, e_y), q (0, e_z)], V^T x = t / 2, so the exponent is -2 V L V^T.
// About the sector axis a of a pose with a roll sector the information is replaced by
// 1 / sigma^2 with sigma the sector (none for a whole turn).
// The camera pose's error, independent of the fit's, adds its covariance (pose_variance per
// axis [rad^2]) before the inversion.
Eigen::Matrix4d poseExponent(const RefinedPose& pose, double concentration, double pose_variance) {
  const Eigen::Vector4d& q = pose.orientation;
  Eigen::Matrix3d information = 0.5 * concentration * Eigen::Matrix3d::Identity();
  if (pose.rotation_covariance.trace() > 0.0) information = pose.rotation_covariance.inverse();
  if (pose_variance > 0.0) {
    information =
        (information.inverse() + pose_variance * Eigen::Matrix3d::Identity()).inverse().eval();
  }
  if (pose.roll_sector_deg > 0.0) {
    const Eigen::Vector3d a = pose.sector_axis.normalized();
    const Eigen::Matrix3d across = Eigen::Matrix3d::Identity() - a * a.transpose();
    const double sigma = pose.roll_sector_deg * M_PI / 180.0;
    const double about_axis = pose.roll_sector_deg >= 180.0 ? 0.0 : 1.0 / (sigma * sigma);
    // Never sharper about the axis than the fit itself says.
    information = across * information * across +
                  std::min(about_axis, a.dot(information * a)) * a * a.transpose();
  }
  Eigen::Matrix<double, 4, 3> turns;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d e = Eigen::Vector3d::Unit(i);
    turns.col(i) = quaternionMultiply(q, Eigen::Vector4d(0.0, e.x(), e.y(), e.z()));
  }
  return -2.0 * turns * information * turns.transpose();
}

// A camera pose or model error [unit, RMS] must be a finite number >= 0.
void checkError(double value, const char* what, const char* unit) {
  if (!std::isfinite(value) || value < 0.0) {
    throw Error(std::string(what) + " must be a finite number >= 0, got " + std::to_string(value) +
                " " + unit);
  }
}

}  // namespace

double measurementLogWeight(const RefinedPose& pose, const RefinedPose& best,
                            const RefinedFusionParameters& parameters) {
  return parameters.likelihood_scale * (pose.score.score() - best.score.score());
}

BinghamMixture refinedMeasurement(const RefinementResult& result,
                                  const RefinedFusionParameters& parameters) {
  if (!(parameters.concentration > 0.0) || !std::isfinite(parameters.concentration) ||
      !(parameters.likelihood_scale > 0.0) || !std::isfinite(parameters.likelihood_scale)) {
    throw Error("refinement's fusion concentration and likelihood scale must be positive");
  }
  if (!(parameters.outlier_weight > 0.0 && parameters.outlier_weight < 1.0)) {
    throw Error("refinement's outlier weight must be in (0, 1), got " +
                std::to_string(parameters.outlier_weight));
  }
  // All of them here, before the estimator fuses anything: the position's covariance uses the
  // last two after the fusion.
  checkError(parameters.camera_pose_uncertainty_deg, "the camera pose uncertainty", "deg");
  checkError(parameters.camera_pose_uncertainty_mm, "the camera pose uncertainty", "mm");
  checkError(parameters.model_error_mm, "the model error", "mm");
  if (result.kept.empty()) throw Error("no verified poses to fuse");
  const double per_axis = parameters.camera_pose_uncertainty_deg * M_PI / 180.0 / std::sqrt(3.0);
  std::vector<double> log_weights;
  std::vector<BinghamDistribution> components;
  double total = 0.0;
  std::vector<RefinedPose> poses = result.kept;
  poses.insert(poses.end(), result.alternatives.begin(), result.alternatives.end());
  for (const RefinedPose& pose : poses) {
    components.push_back(BinghamDistribution::fromExponentMatrix(
        poseExponent(pose, parameters.concentration, per_axis * per_axis)));
    log_weights.push_back(measurementLogWeight(pose, result.kept.front(), parameters));
    total += std::exp(log_weights.back());
  }
  // The outlier share of the whole measurement's mass.
  log_weights.push_back(
      std::log(parameters.outlier_weight / (1.0 - parameters.outlier_weight) * total));
  components.emplace_back();
  return BinghamMixture::fromLogWeights(log_weights, std::move(components));
}

}  // namespace vdc
