#include "view_direction_classification/estimation/orientation_estimator.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <string>
#include <utility>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/learning/feature_selection.h"
#include "view_direction_classification/features/fpfh_features.h"
#include "view_direction_classification/training/model_training.h"
#include "view_direction_classification/common/quaternion.h"
#include "view_direction_classification/estimation/view_measurement.h"

namespace vdc {
namespace {

using Clock = std::chrono::steady_clock;

double millisecondsBetween(Clock::time_point start, Clock::time_point end) {
  return std::chrono::duration<double, std::milli>(end - start).count();
}

// Mean angle between each training direction and its nearest neighbour: the grid spacing that
// sets the default girdle width.
double meanNeighbourAngle(const std::vector<Eigen::Vector3d>& directions) {
  double sum = 0.0;
  for (std::size_t i = 0; i < directions.size(); ++i) {
    double best = -1.0;
    for (std::size_t j = 0; j < directions.size(); ++j) {
      if (i != j) best = std::max(best, directions[i].dot(directions[j]));
    }
    sum += std::acos(std::clamp(best, -1.0, 1.0));
  }
  return sum / static_cast<double>(directions.size());
}

// The smallest rotation taking unit vector `from` onto unit vector `to`, as a (w, x, y, z)
// quaternion.
Eigen::Vector4d rotationBetween(const Eigen::Vector3d& from, const Eigen::Vector3d& to) {
  return fromEigenQuaternion(Eigen::Quaterniond::FromTwoVectors(from, to));
}

OrientationFilterOptions filterOptionsOf(const EstimatorParameters& parameters) {
  OrientationFilterOptions options;
  options.reduction.max_components = parameters.max_components;
  options.reduction.relative_weight_threshold = parameters.belief_weight_floor;
  // The belief's entropy is published with every estimate: 1000 draws keep it at a few ms with
  // a standard error of a few hundredths of a nat.
  options.entropy_samples = 1000;
  return options;
}

void checkParameters(const EstimatorParameters& p) {
  if (p.max_components < 1) {
    throw Error("max_components must be at least 1, got " + std::to_string(p.max_components));
  }
  if (p.min_features < 1) {
    throw Error("min_features must be at least 1, got " + std::to_string(p.min_features));
  }
  if (!(p.min_weight >= 0.0 && p.min_weight < 1.0)) {
    throw Error("min_weight must lie in [0, 1), got " + std::to_string(p.min_weight));
  }
  if (!(p.belief_weight_floor >= 0.0 && p.belief_weight_floor < 1.0)) {
    throw Error("belief_weight_floor must lie in [0, 1), got " +
                std::to_string(p.belief_weight_floor));
  }
  if (!std::isfinite(p.kappa)) throw Error("kappa must be finite");
  checkSegmentationParameters(p.segmentation);
}

}  // namespace

OrientationEstimator::OrientationEstimator(std::shared_ptr<const ModelBundle> model,
                                           EstimatorParameters parameters)
    : model_(std::move(model)),
      parameters_(std::move(parameters)),
      kappa_(0.0),
      filter_(filterOptionsOf(parameters_)) {
  if (!model_) throw Error("the orientation estimator needs a model bundle");
  if (model_->view_directions.size() < 2) {
    throw Error("the model bundle has fewer than two viewing directions");
  }
  checkParameters(parameters_);
  if (parameters_.n_feat <= 0) parameters_.n_feat = model_->parameters.n_feat;
  kappa_ = parameters_.kappa > 0.0
               ? parameters_.kappa
               : defaultViewConcentration(meanNeighbourAngle(model_->view_directions));
}

ViewUpdate OrientationEstimator::update(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                        const Eigen::Isometry3d& world_from_camera) {
  if (!world_from_camera.matrix().allFinite()) {
    throw Error("the camera pose given to the orientation estimator is not finite");
  }
  ViewUpdate result;
  const Clock::time_point start = Clock::now();

  SegmentationParameters segmentation = parameters_.segmentation;
  segmentation.roi_centre = world_from_camera.inverse() * segmentation.roi_centre;
  const pcl::PointCloud<pcl::PointXYZ> object = segmentObject(cloud, segmentation);
  const Clock::time_point segmented = Clock::now();
  result.timing.segmentation = millisecondsBetween(start, segmented);
  result.object_points = static_cast<int>(object.size());
  auto skip = [&](std::string reason) {
    result.skip_reason = std::move(reason);
    result.timing.total = millisecondsBetween(start, Clock::now());
    return result;
  };
  if (object.size() < static_cast<std::size_t>(parameters_.min_features)) {
    return skip("the cloud has " + std::to_string(object.size()) +
                " object points after segmentation, too few for features");
  }

  const FeatureSet features =
      computeFeatures(object, featureParametersOf(model_->parameters), Eigen::Vector3f::Zero());
  const Clock::time_point described = Clock::now();
  result.timing.features = millisecondsBetween(segmented, described);
  result.features = static_cast<int>(features.size());
  if (features.size() < static_cast<std::size_t>(parameters_.min_features)) {
    return skip("the view gave " + std::to_string(features.size()) + " features, fewer than " +
                std::to_string(parameters_.min_features));
  }

  const Eigen::MatrixXf probabilities = model_->classifier.predict(features.descriptors);
  result.p_sum = summedDistribution(probabilities, parameters_.n_feat);
  const Clock::time_point classified = Clock::now();
  result.timing.classification = millisecondsBetween(described, classified);

  // The classifier tells the direction from the object to the camera; the camera sees the
  // object along the ray to its centroid, which is the optical axis only for a centred object.
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const pcl::PointXYZ& p : object.points) centroid += p.getVector3fMap().cast<double>();
  centroid /= static_cast<double>(object.size());
  const BinghamMixture camera_frame =
      viewMeasurement(result.p_sum, model_->view_directions, kappa_, 0.0, parameters_.min_weight);
  const Eigen::Vector4d line_of_sight =
      rotationBetween(Eigen::Vector3d(0, 0, -1), -centroid.normalized());
  const Eigen::Vector4d q_WC = fromEigenQuaternion(Eigen::Quaterniond(world_from_camera.linear()));
  const BinghamMixture measurement = cameraToFixedFrame(camera_frame.rotated(line_of_sight), q_WC);
  const Clock::time_point measured = Clock::now();
  result.timing.measurement = millisecondsBetween(classified, measured);

  filter_.update(measurement);
  map_cache_.reset();
  result.updated = true;
  result.observed_centroid_world = world_from_camera * centroid;
  last_centroid_world_ = result.observed_centroid_world;
  last_camera_position_world_ = world_from_camera.translation();
  const Clock::time_point fused = Clock::now();
  result.timing.fusion = millisecondsBetween(measured, fused);
  result.timing.total = millisecondsBetween(start, fused);
  return result;
}

void OrientationEstimator::reset() {
  filter_.reset();
  map_cache_.reset();
  last_centroid_world_.reset();
  last_camera_position_world_.reset();
}

Eigen::Vector4d OrientationEstimator::mapOrientation() const {
  if (!map_cache_) map_cache_ = filter_.mapEstimate();
  return *map_cache_;
}

double OrientationEstimator::entropy() const { return filter_.entropy(); }

std::optional<Eigen::Vector3d> OrientationEstimator::positionEstimate() const {
  if (!last_centroid_world_ || !last_camera_position_world_) return std::nullopt;
  const Eigen::Matrix3d R_WO = quaternionToRotationMatrix(mapOrientation());
  Eigen::Vector3d towards_camera = *last_camera_position_world_ - *last_centroid_world_;
  if (towards_camera.norm() < 1e-9) return *last_centroid_world_;
  towards_camera = R_WO.transpose() * towards_camera.normalized();
  int nearest = 0;
  double best = -2.0;
  for (std::size_t m = 0; m < model_->view_directions.size(); ++m) {
    const double cosine = model_->view_directions[m].dot(towards_camera);
    if (cosine > best) {
      best = cosine;
      nearest = static_cast<int>(m);
    }
  }
  const Eigen::Vector3d offset = model_->centroid_offsets.row(nearest).transpose();
  return Eigen::Vector3d(*last_centroid_world_ - R_WO * offset);
}

Eigen::Matrix3d OrientationEstimator::orientationCovariance() const {
  // Spread of the belief around its MAP, as world-frame rotation vectors of q_s (x) q_MAP^-1,
  // from a fixed-seed sample so repeated calls agree.
  constexpr int kSamples = 300;
  const Eigen::Vector4d map = mapOrientation();
  std::mt19937_64 generator(7);
  const std::vector<Eigen::Vector4d> samples = belief().sample(kSamples, generator);
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector4d& q : samples) {
    Eigen::Vector4d delta = quaternionMultiply(q, quaternionConjugate(map));
    if (delta(0) < 0) delta = -delta;
    const double half_angle = std::atan2(delta.tail<3>().norm(), delta(0));
    const double sine = delta.tail<3>().norm();
    const Eigen::Vector3d rotation_vector =
        sine > 1e-12 ? Eigen::Vector3d(delta.tail<3>() / sine * 2.0 * half_angle)
                     : Eigen::Vector3d(2.0 * delta.tail<3>());
    covariance += rotation_vector * rotation_vector.transpose();
  }
  return covariance / static_cast<double>(kSamples);
}

}  // namespace vdc
