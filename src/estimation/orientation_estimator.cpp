#include "view_direction_classification/estimation/orientation_estimator.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include "view_direction_classification/bingham/bingham.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/quaternion.h"
#include "view_direction_classification/estimation/camera_pose_covariance.h"
#include "view_direction_classification/estimation/refined_position.h"
#include "view_direction_classification/estimation/verification_scene.h"
#include "view_direction_classification/estimation/view_measurement.h"
#include "view_direction_classification/features/fpfh_features.h"
#include "view_direction_classification/learning/feature_selection.h"
#include "view_direction_classification/training/model_training.h"

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

// Below this likelihood exponent a view adds (next to) nothing to the belief: it is not new.
constexpr double kMinLikelihoodExponent = 0.01;
// Hypotheses per belief component for the information-gain test (as the next-best-view service's
// default).
constexpr int kGainSamplesPerComponent = 8;

double largestCentroidOffset(const ModelBundle& model) {
  return model.centroid_offsets.rows() > 0 ? model.centroid_offsets.rowwise().norm().maxCoeff()
                                           : 0.0;
}

// The largest distance of the bounding box's corners from the object's origin.
double boundingRadius(const Eigen::AlignedBox3d& bounds) {
  double radius = 0.0;
  for (int corner = 0; corner < 8; ++corner) {
    radius = std::max(radius,
                      bounds.corner(static_cast<Eigen::AlignedBox3d::CornerType>(corner)).norm());
  }
  return radius;
}

// A plane n . x + d = 0 of the camera frame in the fixed frame.
Eigen::Vector4d planeInWorld(const Eigen::Vector4d& plane,
                             const Eigen::Isometry3d& world_from_camera) {
  const Eigen::Vector3d normal = world_from_camera.linear() * plane.head<3>();
  return Eigen::Vector4d(normal.x(), normal.y(), normal.z(),
                         plane(3) - normal.dot(world_from_camera.translation()));
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
  options.sharpness_ratio = parameters.sharpness_ratio;
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
  checkSharpnessRatio(p.sharpness_ratio);
  if (!std::isfinite(p.kappa)) throw Error("kappa must be finite");
  if (!(p.psum_exponent > 0.0) || !std::isfinite(p.psum_exponent)) {
    throw Error("psum_exponent must be finite and positive, got " +
                std::to_string(p.psum_exponent));
  }
  if (p.refinement_views < 1) {
    throw Error("refinement_views must be at least 1, got " + std::to_string(p.refinement_views));
  }
  if (!(p.max_object_shift >= 0.0) || !std::isfinite(p.max_object_shift)) {
    throw Error("max_object_shift must be a finite length >= 0, got " +
                std::to_string(p.max_object_shift));
  }
  checkSegmentationParameters(p.segmentation);
  checkFrameSelectionParameters(p.selection);
  checkBeliefCheckParameters(p.belief_check);
}

}  // namespace

OrientationEstimator::OrientationEstimator(std::shared_ptr<const ModelBundle> model,
                                           EstimatorParameters parameters)
    : model_(std::move(model)),
      kappa_(0.0),
      min_view_separation_(0.0),
      independent_view_separation_(0.0),
      max_object_shift_(0.0),
      filter_(filterOptionsOf(parameters)) {
  if (!model_) throw Error("the orientation estimator needs a model bundle");
  if (model_->view_directions.size() < 2) {
    throw Error("the model bundle has fewer than two viewing directions");
  }
  if (!model_->bounds.isEmpty()) extent_ = ObjectExtent::of(model_->bounds);
  setParameters(std::move(parameters));
}

void OrientationEstimator::setParameters(EstimatorParameters parameters) {
  // Everything is checked and derived into locals first, so a refused value changes nothing.
  checkParameters(parameters);
  const SegmentationParameters& segmentation = parameters.segmentation;
  if (segmentation.mode == SegmentationMode::kScene ||
      segmentation.mode == SegmentationMode::kLabels) {
    throw Error("segmentation '" + segmentationModeName(segmentation.mode) +
                "' runs in the scene layer (SceneEstimator), which gives each object's "
                "estimator 'none'");
  }
  if (segmentation.mode == SegmentationMode::kTabletop && extent_.diagonal() <= 0.0) {
    throw Error("tabletop segmentation needs the model's extent, and this bundle has none");
  }
  const OrientationFilterOptions filter_options = filterOptionsOf(parameters);
  reduce(BinghamMixture(), filter_options.reduction);  // throws for invalid reduction options

  if (parameters.n_feat <= 0) parameters.n_feat = model_->parameters.n_feat;
  const double spacing = meanNeighbourAngle(model_->view_directions);
  const FrameSelectionParameters& selection = parameters.selection;
  // Visible parts' centroids lie within the largest offset of the origin: two views of a static
  // object cannot see centroids further apart than twice that (plus noise and clutter).
  const double offset = largestCentroidOffset(*model_);
  SightingParameters sighting;
  if (segmentation.mode == SegmentationMode::kNone) {
    sighting.radius = 0.0;  // the whole cloud is the object
    sighting.min_points = parameters.min_features;
  } else {
    sighting.radius = offset + boundingRadius(model_->bounds) + segmentation.cluster_tolerance;
    sighting.min_points = segmentation.min_cluster_points;
  }
  sighting.see_through_distance = std::max(0.25 * extent_.sizes.minCoeff(), 0.01);
  sighting.table_distance = segmentation.plane_distance;
  // Rebuilt on every call (a reconfigure is rare; its cost is the refiner's set-up).
  std::shared_ptr<const PoseRefiner> refiner, search_refiner;
  if (parameters.refinement == RefinementMode::kIcp) {
    refiner = std::make_shared<const PoseRefiner>(*model_, parameters.refinement_parameters);
    if (parameters.belief_check.search_below_score > 0.0) {
      search_refiner = std::make_shared<const PoseRefiner>(
          *refiner, searchRefinementParameters(parameters.refinement_parameters,
                                               static_cast<int>(model_->view_directions.size()),
                                               parameters.belief_check));
    }
  }

  filter_.setOptions(filter_options);
  refiner_ = std::move(refiner);
  search_refiner_ = std::move(search_refiner);
  kappa_ = parameters.kappa > 0.0 ? parameters.kappa : defaultViewConcentration(spacing);
  min_view_separation_ =
      selection.min_view_separation < 0.0 ? 0.5 * spacing : selection.min_view_separation;
  independent_view_separation_ =
      selection.independent_view_separation < 0.0 ? spacing : selection.independent_view_separation;
  if (selection.min_information_gain <= 0.0) {
    gain_scorer_.reset();
  } else if (!gain_scorer_) {
    gain_scorer_ = std::make_shared<const ViewUtilityScorer>(model_);
  }
  max_object_shift_ =
      parameters.max_object_shift > 0.0 ? parameters.max_object_shift : 2.0 * offset + 0.02;
  sighting_ = sighting;
  parameters_ = std::move(parameters);
  // Fewer views aligned together from the next refinement on: the earlier ones beyond them go.
  while (static_cast<int>(refined_views_.size()) > parameters_.refinement_views - 1) {
    refined_views_.pop_back();
  }
}

ViewUpdate OrientationEstimator::update(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                        const Eigen::Isometry3d& world_from_camera,
                                        std::optional<double> time, const ViewContext& context) {
  if (!world_from_camera.matrix().allFinite()) {
    throw Error("the camera pose given to the orientation estimator is not finite");
  }
  if (context.features && parameters_.segmentation.mode != SegmentationMode::kNone) {
    throw Error(
        "an orientation estimator was given the cloud's features, which it takes only "
        "with segmentation none (the cloud is the object)");
  }
  // An earlier view's search left pending belongs in the belief before this view.
  if (pending_search_) completeSearch(ViewUpdate{});
  ViewUpdate result;
  const Clock::time_point start = Clock::now();
  auto finish = [&]() {
    result.timing.total = millisecondsBetween(start, Clock::now());
    return result;
  };
  bool search_whole_view = false;
  const bool selected = selectFrame(cloud, world_from_camera, time, &result, &search_whole_view);
  const Clock::time_point selection_done = Clock::now();
  result.timing.selection = millisecondsBetween(start, selection_done);
  if (!selected) return finish();
  auto skip = [&](std::string reason) {
    result.outcome = FrameOutcome::kSkipped;
    result.skip_reason = std::move(reason);
    return finish();
  };

  const Eigen::Isometry3d camera_from_world = world_from_camera.inverse();
  SegmentationParameters segmentation = parameters_.segmentation;
  segmentation.roi_centre = camera_from_world * segmentation.roi_centre;
  SegmentationContext expected;
  if (segmentation.mode == SegmentationMode::kTabletop) expected.extent = extent_;
  if (track_ && !search_whole_view)
    expected.expected_centroid = camera_from_world * track_->centroid;
  const ObjectSegment object = segmentObject(cloud, segmentation, expected);
  const Clock::time_point segmented = Clock::now();
  result.timing.segmentation = millisecondsBetween(selection_done, segmented);
  result.object_points = static_cast<int>(object.points.size());
  if (!object.failure.empty()) {
    return skip(search_whole_view && track_
                    ? "the object left its tracked position and " + object.failure
                    : object.failure);
  }
  if (object.points.size() < static_cast<std::size_t>(parameters_.min_features)) {
    return skip("the cloud has " + std::to_string(object.points.size()) +
                " object points after segmentation, too few for features");
  }
  // The classifier tells the direction from the object to the camera; the camera sees the
  // object along the ray to its centroid, which is the optical axis only for a centred object.
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const pcl::PointXYZ& p : object.points.points) {
    centroid += p.getVector3fMap().cast<double>();
  }
  centroid /= static_cast<double>(object.points.size());
  result.observed_centroid_world = world_from_camera * centroid;
  if (track_ && result.reset_reason.empty()) {
    const double shift = (result.observed_centroid_world - track_->centroid).norm();
    if (shift > max_object_shift_) resetForMovedObject(shift, &result);
  }
  if (!track_) track_ = ObjectTrack{};
  track_->centroid = result.observed_centroid_world;
  if (object.table) track_->table = planeInWorld(*object.table, world_from_camera);

  const FeatureSet computed =
      context.features ? FeatureSet{}
                       : computeFeatures(object.points, featureParametersOf(model_->parameters),
                                         Eigen::Vector3f::Zero());
  const FeatureSet& features = context.features ? *context.features : computed;
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

  // Tempered likelihood (doc/method.md section 12): (sum_m p_m B_m)^a ~ sum_m p_m^a B_m^a when
  // the girdles hardly overlap, and B^a is the girdle of concentration a kappa (the normaliser
  // ratio is the same for every m and cancels). The p_sum exponent gamma sharpens the weights
  // alone: (p^gamma)^a = p^(gamma a).
  const double exponent = result.likelihood_exponent;
  const Eigen::VectorXd weights =
      sharpenedDistribution(result.p_sum, parameters_.psum_exponent * exponent);
  const BinghamMixture camera_frame = viewMeasurement(
      weights, model_->view_directions, exponent * kappa_, 0.0, parameters_.min_weight);
  const Eigen::Vector4d line_of_sight =
      rotationBetween(Eigen::Vector3d(0, 0, -1), -centroid.normalized());
  const Eigen::Vector4d q_WC = fromEigenQuaternion(Eigen::Quaterniond(world_from_camera.linear()));
  const BinghamMixture measurement = cameraToFixedFrame(camera_frame.rotated(line_of_sight), q_WC);
  const Clock::time_point measured = Clock::now();
  result.timing.measurement = millisecondsBetween(classified, measured);

  // The view's direction is measured before the fusion moves the position estimate.
  const Eigen::Vector3d view_direction = world_from_camera.translation() - viewingReference();
  filter_.update(measurement);
  map_cache_.reset();
  spread_cache_.reset();
  hypotheses_cache_.reset();
  if (view_direction.norm() > 1e-9) fused_views_.add(view_direction);
  result.outcome = FrameOutcome::kFused;
  result.updated = true;
  last_centroid_world_ = result.observed_centroid_world;
  last_camera_position_world_ = world_from_camera.translation();
  const Clock::time_point fused = Clock::now();
  result.timing.fusion = millisecondsBetween(measured, fused);
  if (refiner_) {
    refineAfterFusion(object.points,
                      context.verification_scene.empty()
                          ? verificationScene(cloud, object, segmentation)
                          : context.verification_scene,
                      world_from_camera, measurement, line_of_sight, context.search, &result);
  }
  const Clock::time_point refined = Clock::now();
  result.timing.refinement = millisecondsBetween(fused, refined);
  result.timing.total = millisecondsBetween(start, refined);
  return result;
}

void OrientationEstimator::refineAfterFusion(const pcl::PointCloud<pcl::PointXYZ>& object_points,
                                             const SceneDepth& scene,
                                             const Eigen::Isometry3d& world_from_camera,
                                             const BinghamMixture& measurement,
                                             const Eigen::Vector4d& line_of_sight,
                                             BeliefSearch search, ViewUpdate* result) {
  // This view first, then the latest earlier ones (thinned to the refiner's voxel): the object
  // stands still and the camera poses are known, so a pose must fit them all.
  RefinementView view;
  view.points = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>(object_points);
  view.world_from_camera = world_from_camera;
  view.scene = scene;
  std::vector<RefinementView> views{view};
  views.insert(views.end(), refined_views_.begin(), refined_views_.end());
  const Eigen::Vector3d position = positionEstimate().value_or(result->observed_centroid_world);
  RefinementResult refinement = refiner_->refine(belief(), position, views);
  rememberRefinedView(view);
  result->refinement_skip_reason = refinement.skip_reason;
  std::optional<DueSearch> due;
  if (search_refiner_ && !refinement.skipped()) {
    due = searchDueOnView(view, views, position, refinement);
  }
  if (!due) {
    fuseRefinement(refinement, world_from_camera.translation(), result);
    return;
  }
  due->measurement = measurement;
  due->line_of_sight = line_of_sight;
  due->refinement = std::move(refinement);
  if (search == BeliefSearch::kDeferred) {
    // The scores of the belief's own poses, for the caller to compare; nothing fused yet.
    if (!due->refinement.kept.empty()) {
      result->verified_score = due->refinement.kept.front().score.score();
      result->identity_score = due->refinement.kept.front().score.identityScore();
    }
    result->search_pending = true;
    pending_search_ = std::move(due);
    return;
  }
  searchBeyondBelief(due->views, due->position, due->belief_pose, due->belief_score,
                     due->measurement, due->line_of_sight, &due->refinement, result);
  fuseRefinement(due->refinement, world_from_camera.translation(), result);
}

ViewUpdate OrientationEstimator::completeSearch(ViewUpdate update) {
  if (!pending_search_) return update;
  const Clock::time_point start = Clock::now();
  DueSearch due = std::move(*pending_search_);
  pending_search_.reset();
  update.search_pending = false;
  update.verified_score.reset();
  update.identity_score.reset();
  searchBeyondBelief(due.views, due.position, due.belief_pose, due.belief_score, due.measurement,
                     due.line_of_sight, &due.refinement, &update);
  fuseRefinement(due.refinement, due.views.front().world_from_camera.translation(), &update);
  const double searched_ms = millisecondsBetween(start, Clock::now());
  update.timing.refinement += searched_ms;
  update.timing.total += searched_ms;
  return update;
}

void OrientationEstimator::fuseRefinement(const RefinementResult& refinement,
                                          const Eigen::Vector3d& camera_position,
                                          ViewUpdate* result) {
  result->fitted_identity_score = bestFittedIdentityScore(refinement);
  if (const RefinedPose* fitted = bestFittedPose(refinement)) {
    result->fitted_pose = fitted->world_from_object;
  } else {
    result->fitted_pose.reset();
  }
  if (refinement.kept.empty()) return;
  filter_.update(refinedMeasurement(refinement, parameters_.refined_fusion));
  map_cache_.reset();
  spread_cache_.reset();
  hypotheses_cache_.reset();
  refined_position_ = refinement.kept.front().world_from_object.translation();
  const RefinedFusionParameters& fusion = parameters_.refined_fusion;
  refined_position_covariance_ = refinedPositionCovariance(refinement, fusion) +
                                 modelErrorPositionCovariance(fusion.model_error_mm) +
                                 cameraPosePositionCovariance(*refined_position_ - camera_position,
                                                              fusion.camera_pose_uncertainty_deg,
                                                              fusion.camera_pose_uncertainty_mm);
  result->refined_poses = static_cast<int>(refinement.kept.size());
  result->verified_score = refinement.kept.front().score.score();
  result->identity_score = refinement.kept.front().score.identityScore();
}

std::optional<OrientationEstimator::DueSearch> OrientationEstimator::searchDueOnView(
    const RefinementView& view, const std::vector<RefinementView>& views,
    const Eigen::Vector3d& position, const RefinementResult& refinement) {
  check_views_.push_front(thinnedView(view, parameters_.refinement_parameters.scene_voxel));
  while (static_cast<int>(check_views_.size()) > parameters_.belief_check.check_views) {
    check_views_.pop_back();
  }
  // The belief's best pose: refinement's, or without one the MAP at the position estimate.
  DueSearch due;
  if (refinement.kept.empty()) {
    due.belief_pose.linear() = quaternionToRotationMatrix(mapOrientation());
    due.belief_pose.translation() = position;
    due.belief_score = verifiedScore(*refiner_, {check_views_.front()}, due.belief_pose);
  } else {
    due.belief_pose = refinement.kept.front().world_from_object;
    due.belief_score = refinement.kept.front().score.score();
  }
  if (due.belief_score >= searchThreshold()) return std::nullopt;
  due.views = views;
  due.position = position;
  return due;
}

double OrientationEstimator::searchThreshold() const {
  const BeliefCheckParameters& check = parameters_.belief_check;
  if (!confirmed_fit_score_) return check.search_below_score;
  return std::min(check.search_below_score, *confirmed_fit_score_ - check.rebuild_margin);
}

void OrientationEstimator::searchBeyondBelief(
    const std::vector<RefinementView>& views, const Eigen::Vector3d& position,
    const Eigen::Isometry3d& belief_pose, double belief_score, const BinghamMixture& measurement,
    const Eigen::Vector4d& line_of_sight, RefinementResult* refinement, ViewUpdate* result) {
  result->searched = true;
  RefinementResult search = search_refiner_->refine(
      searchBelief(line_of_sight, views.front().world_from_camera), position, views);
  if (search.kept.empty()) return;
  const std::vector<RefinementView> latest(check_views_.begin(), check_views_.end());
  const BeliefVerdict verdict =
      judgeBelief(*refiner_, latest, belief_pose, search.kept.front().world_from_object,
                  parameters_.belief_check);
  if (!verdict.contradicted) {
    // Nothing fits clearly better: this is what the camera's noise lets a right pose reach, if
    // the pose verifies at all (a pose below min_score says nothing about the camera).
    if (belief_score >= parameters_.refinement_parameters.min_score) {
      confirmed_fit_score_ = belief_score;
    }
    return;
  }
  confirmed_fit_score_.reset();
  char reason[200];
  std::snprintf(reason, sizeof(reason),
                "the geometry contradicted the belief: over the latest %zu views its best pose "
                "verifies at %.3f, a pose outside it at %.3f",
                latest.size(), verdict.belief_score, verdict.search_score);
  result->rebuild_reason = reason;
  // The earlier views' evidence is in the belief only as the belief: it goes with it, and the
  // belief starts again from this view's measurement and the search's poses.
  filter_.reset();
  filter_.update(measurement);
  *refinement = std::move(search);
}

BinghamMixture OrientationEstimator::searchBelief(
    const Eigen::Vector4d& line_of_sight, const Eigen::Isometry3d& world_from_camera) const {
  const int directions = static_cast<int>(model_->view_directions.size());
  const Eigen::VectorXd uniform = Eigen::VectorXd::Constant(directions, 1.0 / directions);
  const BinghamMixture camera_frame =
      viewMeasurement(uniform, model_->view_directions, kappa_, 0.0, 0.0);
  const Eigen::Vector4d q_WC = fromEigenQuaternion(Eigen::Quaterniond(world_from_camera.linear()));
  return cameraToFixedFrame(camera_frame.rotated(line_of_sight), q_WC);
}

void OrientationEstimator::rememberRefinedView(const RefinementView& view) {
  const int keep = parameters_.refinement_views - 1;
  if (keep <= 0) {
    refined_views_.clear();
    return;
  }
  refined_views_.push_front(thinnedView(view, parameters_.refinement_parameters.scene_voxel));
  while (static_cast<int>(refined_views_.size()) > keep) refined_views_.pop_back();
}

bool OrientationEstimator::selectFrame(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                       const Eigen::Isometry3d& world_from_camera,
                                       std::optional<double> time, ViewUpdate* result,
                                       bool* search_whole_view) {
  if (time) {
    const StampedPose current{world_from_camera, *time};
    std::optional<std::string> jump;
    if (last_pose_) jump = cameraJumpReason(*last_pose_, current, parameters_.selection);
    last_pose_ = current;
    if (jump) {
      result->skip_reason = *jump;
      return false;
    }
  }
  if (!track_) return true;  // nothing seen yet: every frame is looked at in full

  const ObjectSighting sighting =
      lookForTrackedObject(cloud, world_from_camera, *track_, sighting_);
  if (sighting.status == SightingStatus::kNotInView) {
    result->skip_reason = "the object is not in view where it was tracked (" +
                          std::to_string(sighting.points) +
                          " points there: out of the image, occluded or too far)";
    return false;
  }
  if (sighting.status == SightingStatus::kLeft) {
    *search_whole_view = true;  // the place is empty: look for the object in the whole view
    return true;
  }
  const double shift = (sighting.centroid - track_->centroid).norm();
  if (shift > max_object_shift_) {
    resetForMovedObject(shift, result);
    *search_whole_view = true;
    return true;
  }
  track_->centroid = sighting.centroid;
  if (fused_views_.size() == 0) return true;

  const Eigen::Vector3d camera = world_from_camera.translation();
  const Eigen::Vector3d direction = camera - viewingReference();
  if (direction.norm() < 1e-6) {
    result->skip_reason = "the camera is at the object's position";
    return false;
  }
  result->view_separation = fused_views_.separationFrom(direction);
  result->likelihood_exponent =
      likelihoodExponent(result->view_separation, independent_view_separation_);
  if (isNewView(camera, result->view_separation)) return true;
  result->outcome = FrameOutcome::kNotNovel;
  return false;
}

bool OrientationEstimator::isNewView(const Eigen::Vector3d& camera_position,
                                     double separation) const {
  const double exponent = likelihoodExponent(separation, independent_view_separation_);
  if (exponent < kMinLikelihoodExponent) return false;
  if (separation >= min_view_separation_) return true;
  if (!gain_scorer_) return false;
  if (!hypotheses_cache_) {
    hypotheses_cache_ = beliefHypotheses(belief(), kGainSamplesPerComponent);
  }
  const double gain =
      gain_scorer_->informationGain(camera_position, viewingReference(), *hypotheses_cache_);
  return exponent * gain >= parameters_.selection.min_information_gain;
}

void OrientationEstimator::resetForMovedObject(double shift, ViewUpdate* result) {
  char text[200];
  std::snprintf(text, sizeof(text),
                "the object moved: it is seen %.3f m from where it was tracked (more than "
                "max_object_shift %.3f m)",
                shift, max_object_shift_);
  reset();
  result->reset_reason = text;
  result->view_separation = M_PI;
  result->likelihood_exponent = 1.0;
}

Eigen::Vector3d OrientationEstimator::viewingReference() const {
  if (const std::optional<Eigen::Vector3d> position = positionEstimate()) return *position;
  return track_ ? track_->centroid : Eigen::Vector3d::Zero();
}

void OrientationEstimator::reset() {
  // The camera's last pose stays: the tf-jump check is about the camera, not the object.
  filter_.reset();
  map_cache_.reset();
  spread_cache_.reset();
  hypotheses_cache_.reset();
  fused_views_.clear();
  track_.reset();
  last_centroid_world_.reset();
  last_camera_position_world_.reset();
  refined_position_.reset();
  refined_position_covariance_.reset();
  refined_views_.clear();
  check_views_.clear();
  confirmed_fit_score_.reset();
  pending_search_.reset();
}

Eigen::Vector4d OrientationEstimator::mapOrientation() const {
  if (!map_cache_) map_cache_ = filter_.mapEstimate();
  return *map_cache_;
}

double OrientationEstimator::entropy() const { return filter_.entropy(); }

std::optional<Eigen::Vector3d> OrientationEstimator::positionEstimate() const {
  if (refined_position_) return refined_position_;
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

const BeliefSpread& OrientationEstimator::spread() const {
  if (!spread_cache_) spread_cache_ = beliefSpread(belief(), mapOrientation());
  return *spread_cache_;
}

}  // namespace vdc
