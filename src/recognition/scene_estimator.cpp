#include "view_direction_classification/recognition/scene_estimator.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <utility>

#include "explained_pieces.h"
#include "piece_groups.h"
#include "seen_through.h"
#include "view_direction_classification/common/elapsed_time.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/parallel_for.h"
#include "view_direction_classification/estimation/verification_scene.h"
#include "view_direction_classification/recognition/instance_association.h"

namespace vdc {
namespace {

using Clock = std::chrono::steady_clock;

// An identified object sharing at least this much of its hull's volume with an instance of its
// model (InstanceOverlap::overlap) is that instance. Two mugs side by side share nothing, or a
// few percent where a handle reaches into the other's hull; a mug moved 6 cm shares 0.13-0.25,
// 4 cm 0.36-0.47 (instance_overlap_test.cpp).
constexpr double kSameObjectOverlap = 0.1;

// Two identified objects of different models collide (InstanceCollision) when a tenth of either's
// surface lies more than 1 cm inside the other: objects side by side or touching share nothing,
// and a pose error of a few millimetres moves no sample that deep.
constexpr double kCollisionDepth = 0.01;
constexpr double kMinCollision = 0.1;

// [m] The camera sees past an unknown object's centroid by at least this where the object is
// gone: the centroid of what was seen of it lies inside it, centimetres above the table.
constexpr double kEmptyPlaceDepth = 0.02;

// Whether an unknown object's place is empty on this frame: no candidate within
// association_distance of its centroid (fixed frame), and the camera sees through the centroid.
bool placeEmptied(const Eigen::Vector3d& centroid, const std::vector<CandidateOutcome>& candidates,
                  const SceneDepth& scene, const Eigen::Isometry3d& camera_from_world,
                  double association_distance) {
  for (const CandidateOutcome& candidate : candidates) {
    if ((candidate.centroid_world - centroid).norm() < association_distance) return false;
  }
  return seenThrough(scene, (camera_from_world * centroid).cast<float>(), kEmptyPlaceDepth);
}

void checkNonNegative(double value, const char* name) {
  if (!(value >= 0.0) || !std::isfinite(value)) {
    throw Error(std::string("scene estimator ") + name + " must be a finite number >= 0, got " +
                std::to_string(value));
  }
}

pcl::PointCloud<pcl::PointXYZ> candidatePoints(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                               const SceneCandidate& candidate) {
  pcl::PointCloud<pcl::PointXYZ> points;
  points.reserve(candidate.indices.size());
  for (int index : candidate.indices) points.push_back(cloud[index]);
  return points;
}

// label_models' classes mapped to library indices, so that a typo in a model name is a start-up
// error rather than a class whose objects are silently never identified.
std::map<std::int64_t, int> labelModelIndices(const ModelLibrary& library,
                                              const std::map<std::int64_t, std::string>& names) {
  std::map<std::int64_t, int> indices;
  for (const auto& [class_id, name] : names) {
    const int found = library.find(name);
    if (found < 0) {
      std::string known;
      for (const LibraryModel& model : library.models())
        known += (known.empty() ? "" : ", ") + model.name;
      throw Error("label_models maps class " + std::to_string(class_id) + " to '" + name +
                  "', which is no model of the library (" + known + ")");
    }
    indices[class_id] = found;
  }
  return indices;
}

}  // namespace

void checkSceneEstimatorParameters(const SceneEstimatorParameters& p) {
  checkSceneSegmentationParameters(p.segmentation);
  checkIdentificationParameters(p.identification);
  checkNonNegative(p.association_distance, "association_distance");
  checkUnknownRetryParameters(p.unknown_retry);
  checkPartSearchParameters(p.part_search);
  checkNonNegative(p.min_camera_translation, "min_camera_translation");
  checkNonNegative(p.min_camera_rotation, "min_camera_rotation");
  checkNonNegative(p.part_tolerance, "part_tolerance");
  checkNonNegative(p.forget_gone_after, "forget_gone_after");
  if (p.absent_views < 1) {
    throw Error(
        "scene estimator absent_views must be >= 1 (frames of absence before an instance "
        "is gone), got " +
        std::to_string(p.absent_views));
  }
  if (!(p.min_explained_fraction >= 0.0 && p.min_explained_fraction <= 1.0)) {
    throw Error("scene estimator min_explained_fraction must be in [0, 1], got " +
                std::to_string(p.min_explained_fraction));
  }
  if (p.max_identifications < 0) {
    throw Error("scene estimator max_identifications must be >= 0, got " +
                std::to_string(p.max_identifications));
  }
  if (p.max_growth_tries < 0) {
    throw Error("scene estimator max_growth_tries must be >= 0, got " +
                std::to_string(p.max_growth_tries));
  }
}

SceneEstimator::SceneEstimator(ModelLibrary library, SceneEstimatorParameters parameters)
    : library_(std::move(library)),
      parameters_(std::move(parameters)),
      unknowns_(parameters_.association_distance, parameters_.unknown_retry) {
  checkSceneEstimatorParameters(parameters_);
  // The candidate is the object: the instance estimators segment nothing.
  parameters_.instance.segmentation.mode = SegmentationMode::kNone;
  // One idle estimator per model, built with the instance settings (which throws for bad
  // ones), and kept: every candidate's fresh estimator shares its refiners' model surfaces
  // (k-d trees, distance fields, symmetry axes), which live only while some refiner holds them.
  // Without these, each candidate rebuilt them for every model that fits it.
  for (const LibraryModel& model : library_.models()) {
    surface_holders_.push_back(
        std::make_unique<OrientationEstimator>(model.bundle, parameters_.instance));
  }
  instances_named_.assign(library_.size(), 0);
  for (const LibraryModel& model : library_.models()) {
    explanations_.push_back(std::make_unique<InstanceExplanation>(*model.bundle));
  }
  shapes_ = std::make_unique<ShapeAlternative>(
      library_, parameters_.instance.refinement_parameters.verification,
      parameters_.identification.unknown_score);
  label_model_index_ = labelModelIndices(library_, parameters_.label_models);
  presence_ = std::make_unique<InstancePresence>(
      library_, parameters_.instance.refinement_parameters.verification, parameters_.absent_views,
      parameters_.forget_gone_after);
  overlap_ = std::make_unique<InstanceOverlap>(library_);
  collision_ = std::make_unique<InstanceCollision>(library_);
  part_search_ = std::make_unique<PartSearch>(parameters_.instance, parameters_.part_search,
                                              parameters_.identification.threads);
}

const ObjectInstance* SceneEstimator::instance(int id) const {
  for (const ObjectInstance& instance : instances_) {
    if (instance.id == id) return &instance;
  }
  return nullptr;
}

void SceneEstimator::reset() {
  instances_.clear();
  unknowns_.clear();
  last_segmented_camera_.reset();
}

bool SceneEstimator::resetInstance(int id) {
  const auto it = std::find_if(instances_.begin(), instances_.end(),
                               [id](const ObjectInstance& instance) { return instance.id == id; });
  if (it == instances_.end()) return false;
  instances_.erase(it);
  return true;
}

bool SceneEstimator::cameraMoved(const Eigen::Isometry3d& world_from_camera) const {
  if (!last_segmented_camera_) return true;
  const double translation =
      (world_from_camera.translation() - last_segmented_camera_->translation()).norm();
  const Eigen::AngleAxisd turn(last_segmented_camera_->linear().transpose() *
                               world_from_camera.linear());
  return translation >= parameters_.min_camera_translation ||
         std::abs(turn.angle()) >= parameters_.min_camera_rotation;
}

SceneUpdate SceneEstimator::update(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                   const Eigen::Isometry3d& world_from_camera,
                                   std::optional<double> time) {
  if (!world_from_camera.matrix().allFinite()) {
    throw Error("the camera pose given to the scene estimator is not finite");
  }
  // A still camera's frame costs next to nothing: it is not segmented.
  if (!cameraMoved(world_from_camera)) {
    return update(cloud, SceneSegments{}, world_from_camera, time);
  }
  const Clock::time_point start = Clock::now();
  const SceneSegments segments = segmentScene(cloud, parameters_.segmentation);
  const double segmentation_ms = millisecondsSince(start);
  SceneUpdate result = update(cloud, segments, world_from_camera, time);
  result.segmentation_ms = segmentation_ms;
  result.total_ms += segmentation_ms;
  return result;
}

SceneUpdate SceneEstimator::update(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                   const SceneSegments& segments,
                                   const Eigen::Isometry3d& world_from_camera,
                                   std::optional<double> time) {
  if (!world_from_camera.matrix().allFinite()) {
    throw Error("the camera pose given to the scene estimator is not finite");
  }
  const Clock::time_point start = Clock::now();
  SceneUpdate result;
  if (!cameraMoved(world_from_camera)) {
    result.skip_reason = "the camera has not moved since the last segmented frame";
    result.total_ms = millisecondsSince(start);
    return result;
  }
  result.segmented = true;
  result.planes = static_cast<int>(segments.planes.size());
  result.dropped_clusters = segments.dropped_clusters;
  result.segmentation_note = segments.note;
  last_segmented_camera_ = world_from_camera;
  std::vector<Eigen::Vector4d> supports;
  for (const SupportPlane& plane : segments.planes) supports.push_back(plane.coefficients);
  // Indexed once for every candidate's and model's verifiers of this frame.
  const SceneDepth scene =
      indexRays(verificationScene(cloud, supports, parameters_.segmentation.plane_distance));

  std::vector<FrameCandidate> candidates =
      frameCandidates(cloud, segments, world_from_camera, &result);
  Clock::time_point stage_start = Clock::now();
  result.stage_ms.preparation = millisecondsSince(start);
  const Eigen::Isometry3d camera_from_world = world_from_camera.inverse();
  unknowns_.forgetIf([&](const Eigen::Vector3d& centroid) {
    return placeEmptied(centroid, result.candidates, scene, camera_from_world,
                        parameters_.association_distance);
  });
  presence_->checkPlaces(instances_, scene, world_from_camera);
  associate(candidates, result);
  std::vector<int> associated;  // ids: updateAssignedInstances may drop instances
  for (const FrameCandidate& candidate : candidates) {
    if (candidate.instance >= 0) associated.push_back(instances_[candidate.instance].id);
  }
  updateAssignedInstances(candidates, scene, world_from_camera, time, &result);
  result.stage_ms.instances = millisecondsSince(stage_start);
  stage_start = Clock::now();
  // Before identification, which takes an instance whose place was seen free for a moved one.
  result.gone = presence_->observe(instances_, associated, scene, world_from_camera, time);
  // The rest, largest first (segmentScene's order): new instances, parts of the instances found
  // on this frame, or unknown; then what is left, in groups of pieces beside each other.
  int identifications = 0;
  std::vector<bool> unknown_alone(candidates.size(), false);
  const std::set<std::vector<std::size_t>> clusters_tried = identifyWholeClusters(
      cloud, segments, candidates, scene, world_from_camera, time, &identifications, &result);
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    if (candidates[c].instance >= 0 || candidates[c].ignored) continue;
    CandidateOutcome& outcome = result.candidates[c];
    const int part_of = explainingInstance(candidates[c]);
    if (part_of >= 0) {
      outcome.instance = instances_[part_of].id;
      outcome.note = "a part of " + instances_[part_of].name;
    } else if (std::string why = unknowns_.notRetriedBecause(outcome.centroid_world, outcome.sides,
                                                             world_from_camera.translation(),
                                                             candidates[c].points_world);
               !why.empty()) {
      outcome.note = why;
    } else if (identifications >= parameters_.max_identifications) {
      outcome.note = "not identified: max_identifications reached on this frame";
    } else {
      ++identifications;
      unknown_alone[c] = identify(candidates[c], scene, world_from_camera, time, &outcome, true,
                                  unassignedBesides(candidates, c)) < 0;
    }
  }
  result.stage_ms.identification = millisecondsSince(stage_start);
  stage_start = Clock::now();
  identifyAdjacentGroups(cloud, segments, candidates, scene, world_from_camera, time,
                         clusters_tried, &identifications, &result);
  growNewInstances(cloud, segments, candidates, scene, world_from_camera, time, &result);
  result.stage_ms.groups = millisecondsSince(stage_start);
  stage_start = Clock::now();
  identifyParts(cloud, segments, candidates, unknown_alone, scene, world_from_camera, time,
                &result);
  result.stage_ms.parts = millisecondsSince(stage_start);
  dropUnlikelyInstances(&result);  // those that yielded to a colliding identification
  result.forgotten = presence_->forgetGone(instances_, time);
  result.total_ms = millisecondsSince(start);
  return result;
}

std::vector<SceneEstimator::FrameCandidate> SceneEstimator::frameCandidates(
    const pcl::PointCloud<pcl::PointXYZ>& cloud, const SceneSegments& segments,
    const Eigen::Isometry3d& world_from_camera, SceneUpdate* result) const {
  std::vector<FrameCandidate> candidates;
  const Eigen::Isometry3f world_from_camera_f = world_from_camera.cast<float>();
  for (const SceneCandidate& candidate : segments.candidates) {
    FrameCandidate frame_candidate;
    frame_candidate.points = candidatePoints(cloud, candidate);
    if (candidate.support >= 0) {
      frame_candidate.support = segments.planes[candidate.support].coefficients;
      frame_candidate.up = frame_candidate.support->head<3>().cast<float>();
    }
    for (const auto& p : frame_candidate.points) {
      frame_candidate.points_world.push_back(world_from_camera_f * p.getVector3fMap());
    }
    CandidateOutcome outcome;
    outcome.centroid_world = world_from_camera * candidate.centroid;
    outcome.sides = candidate.extent;
    outcome.points = candidate.pointCount();
    restrictToClass(candidate.class_id, &frame_candidate, &outcome);
    candidates.push_back(std::move(frame_candidate));
    result->candidates.push_back(outcome);
  }
  return candidates;
}

void SceneEstimator::restrictToClass(std::int64_t class_id, FrameCandidate* candidate,
                                     CandidateOutcome* outcome) const {
  // Geometric candidates have no class, and without label_models every model may be tried.
  if (class_id < 0 || parameters_.label_models.empty()) return;
  const auto found = label_model_index_.find(class_id);
  if (found == label_model_index_.end()) {
    candidate->ignored = true;
    outcome->note = "ignored: its class " + std::to_string(class_id) + " has no label_models entry";
    return;
  }
  candidate->allowed.assign(static_cast<std::size_t>(library_.size()), false);
  candidate->allowed[static_cast<std::size_t>(found->second)] = true;
}

void SceneEstimator::associate(std::vector<FrameCandidate>& candidates,
                               const SceneUpdate& result) const {
  // Ignored candidates take no part: they must not take an instance's place.
  std::vector<Eigen::Vector3d> centroids, instance_centroids;
  std::vector<std::size_t> taking_part;
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    if (candidates[c].ignored) continue;
    taking_part.push_back(c);
    centroids.push_back(result.candidates[c].centroid_world);
  }
  std::vector<int> present;  // indices into instances_
  for (std::size_t i = 0; i < instances_.size(); ++i) {
    if (outOfPlace(instances_[i])) continue;
    present.push_back(static_cast<int>(i));
    instance_centroids.push_back(instances_[i].centroid_world);
  }
  const std::vector<int> instance_of =
      associateCandidates(centroids, instance_centroids, parameters_.association_distance);
  for (std::size_t k = 0; k < taking_part.size(); ++k) {
    FrameCandidate& candidate = candidates[taking_part[k]];
    candidate.instance = instance_of[k] >= 0 ? present[static_cast<std::size_t>(instance_of[k])]
                                             : explainingInstance(candidate);
  }
}

// Gone instances and those whose place this frame shows free (checkPlaces, and observe after
// it, set last_check from this frame) take no candidate by nearness and explain none: what
// stands there is something else, the object put back or the object moved and turned, and
// identification tells which (sameObject, instanceFor). Taken by a gone elephant's instance, a
// mug put down at its place was never identified, pass after pass; fused into its old belief, a
// mug moved 5 cm and turned kept its old pose for views.
bool SceneEstimator::outOfPlace(const ObjectInstance& instance) {
  return instance.presence.state == InstanceState::kGone ||
         instance.presence.last_check.evidence == PresenceEvidence::kAbsent;
}

int SceneEstimator::explainingInstance(const FrameCandidate& candidate) const {
  for (std::size_t i = 0; i < instances_.size(); ++i) {
    const ObjectInstance& instance = instances_[i];
    if (outOfPlace(instance)) continue;
    const std::optional<Eigen::Isometry3d> world_from_object = believedPose(*instance.estimator);
    if (!world_from_object) continue;
    if (explanations_[instance.model]->explainsPart(candidate.points_world, *world_from_object,
                                                    parameters_.part_tolerance,
                                                    parameters_.min_explained_fraction)) {
      return static_cast<int>(i);
    }
  }
  return -1;
}

void SceneEstimator::updateAssignedInstances(std::vector<FrameCandidate>& candidates,
                                             const SceneDepth& scene,
                                             const Eigen::Isometry3d& world_from_camera,
                                             std::optional<double> time, SceneUpdate* result) {
  // What each instance sees of this frame: its candidates' points together.
  struct InstanceView {
    std::size_t instance = 0;
    int first = -1;  // its largest candidate: where its update is reported
    pcl::PointCloud<pcl::PointXYZ> points;
    Eigen::Vector3f up = Eigen::Vector3f::Zero();
    SceneDepth scene;
    ViewUpdate update;
  };
  std::vector<InstanceView> views;
  for (std::size_t i = 0; i < instances_.size(); ++i) {
    InstanceView view;
    view.instance = i;
    view.scene = scene;
    for (std::size_t c = 0; c < candidates.size(); ++c) {
      if (candidates[c].instance != static_cast<int>(i)) continue;
      view.points += candidates[c].points;
      result->candidates[c].instance = instances_[i].id;
      if (view.first >= 0) {
        result->candidates[c].note = "a part of " + instances_[i].name;
        continue;
      }
      view.first = static_cast<int>(c);
      view.up = candidates[c].up;
      view.scene.support_plane = candidates[c].support;
    }
    if (view.first >= 0) views.push_back(std::move(view));
  }
  // Each instance's estimator is its own: their updates are independent of each other and of
  // the order they run in.
  parallelFor(views.size(), parameters_.identification.threads, [&](int, std::size_t k) {
    InstanceView& view = views[k];
    view.update = instances_[view.instance].estimator->update(
        view.points, world_from_camera, time, {view.scene, BeliefSearch::kWhenDue, nullptr});
  });
  for (InstanceView& view : views) {
    ObjectInstance& instance = instances_[view.instance];
    result->candidates[view.first].update = view.update;
    instance.centroid_world = result->candidates[view.first].centroid_world;
    instance.last_seen = time;
    ++instance.frames_seen;
    if (view.update.outcome == FrameOutcome::kFused) {
      weighIdentity(instance, view.update,
                    shapes_->penalties(view.points, view.up, scene)[instance.model],
                    world_from_camera);
    }
  }
  dropUnlikelyInstances(result);
}

void SceneEstimator::weighIdentity(ObjectInstance& instance, const ViewUpdate& update,
                                   double penalty, const Eigen::Isometry3d& world_from_camera) {
  const double p = std::clamp(instance.identity_probability, 1e-9, 1.0 - 1e-9);
  std::optional<double> score = update.fitted_identity_score;
  if (score) *score -= penalty;
  const double log_odds =
      std::log(p / (1.0 - p)) + identityEvidence(score, parameters_.identification);
  instance.identity_probability = 1.0 / (1.0 + std::exp(-log_odds));
  if (instance.identity_probability < parameters_.identification.drop_probability) {
    // Remembered as unknown from here, so that it is not identified again from the same side.
    unknowns_.remember(instance.centroid_world, Eigen::Vector3d::Zero(),
                       world_from_camera.translation());
  }
}

void SceneEstimator::dropUnlikelyInstances(SceneUpdate* result) {
  for (auto it = instances_.begin(); it != instances_.end();) {
    if (it->identity_probability >= parameters_.identification.drop_probability) {
      ++it;
      continue;
    }
    for (CandidateOutcome& candidate : result->candidates) {
      if (candidate.instance != it->id) continue;
      candidate.dropped = true;
      candidate.note = it->name + " dropped: the views do not support it";
    }
    it = instances_.erase(it);
  }
}

std::set<std::vector<std::size_t>> SceneEstimator::identifyWholeClusters(
    const pcl::PointCloud<pcl::PointXYZ>& cloud, const SceneSegments& segments,
    std::vector<FrameCandidate>& candidates, const SceneDepth& scene,
    const Eigen::Isometry3d& world_from_camera, std::optional<double> time, int* identifications,
    SceneUpdate* result) {
  std::map<int, std::vector<std::size_t>> pieces;  // per cluster, largest first
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    const int cluster = segments.candidates[c].cluster;
    if (cluster < 0 || candidates[c].instance >= 0 || candidates[c].ignored) continue;
    if (explainingInstance(candidates[c]) >= 0) continue;  // a part: the loop after says so
    pieces[cluster].push_back(c);
  }
  std::set<std::vector<std::size_t>> tried;
  for (const auto& [cluster, members] : pieces) {
    if (members.size() < 2) continue;
    identifyPieces(cloud, segments, members, candidates, scene, world_from_camera, time,
                   identifications, result);
    tried.insert(members);
  }
  return tried;
}

void SceneEstimator::identifyAdjacentGroups(
    const pcl::PointCloud<pcl::PointXYZ>& cloud, const SceneSegments& segments,
    std::vector<FrameCandidate>& candidates, const SceneDepth& scene,
    const Eigen::Isometry3d& world_from_camera, std::optional<double> time,
    const std::set<std::vector<std::size_t>>& tried, int* identifications, SceneUpdate* result) {
  std::vector<std::size_t> left;  // the candidates without an instance, most points first
  std::vector<const SceneCandidate*> parts;
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    if (candidates[c].instance >= 0 || candidates[c].ignored) continue;
    if (result->candidates[c].instance >= 0) continue;  // a new instance or a part of one
    left.push_back(c);
    parts.push_back(&segments.candidates[c]);
  }
  // A candidate that an instance explains (one a group found, or one found after the candidate
  // was tried alone) is its part, not a member of a group.
  constexpr int kUnchecked = -2;
  std::vector<int> part_of(candidates.size(), kUnchecked);
  const auto available = [&](std::size_t m) {
    if (candidates[m].instance >= 0) return false;
    if (part_of[m] == kUnchecked) part_of[m] = explainingInstance(candidates[m]);
    return part_of[m] < 0;
  };
  // Each with its members: their points are the group's.
  std::vector<std::pair<CandidateOutcome, std::vector<std::size_t>>> unknown_groups;
  for (const std::vector<std::size_t>& group :
       adjacentCandidateGroups(cloud, parts, parameters_.segmentation.cluster_tolerance)) {
    std::vector<std::size_t> members;
    for (std::size_t k : group) members.push_back(left[k]);
    if (tried.count(members) > 0 || !std::all_of(members.begin(), members.end(), available)) {
      continue;
    }
    CandidateOutcome group_outcome;
    const UnionOutcome outcome =
        identifyPieces(cloud, segments, members, candidates, scene, world_from_camera, time,
                       identifications, result, &group_outcome);
    if (outcome == UnionOutcome::kUnknown) unknown_groups.emplace_back(group_outcome, members);
    // The explanations checked so far knew nothing of the new instance.
    if (outcome == UnionOutcome::kIdentified) {
      std::fill(part_of.begin(), part_of.end(), kUnchecked);
    }
  }
  for (std::size_t c : left) {
    if (candidates[c].instance >= 0 || available(c)) continue;
    result->candidates[c].instance = instances_[part_of[c]].id;
    result->candidates[c].note = "a part of " + instances_[part_of[c]].name;
  }
  // Remembered once every group was tried: a group found unknown must not keep another near it
  // from being tried on this frame (notRetriedBecause knows places, sizes and boxes, not which
  // pieces a union was made of).
  for (const auto& [group, members] : unknown_groups) {
    std::vector<Eigen::Vector3f> points_world;
    for (std::size_t m : members) {
      points_world.insert(points_world.end(), candidates[m].points_world.begin(),
                          candidates[m].points_world.end());
    }
    unknowns_.remember(group.centroid_world, group.sides, world_from_camera.translation(),
                       points_world);
  }
}

SceneEstimator::UnionOutcome SceneEstimator::identifyPieces(
    const pcl::PointCloud<pcl::PointXYZ>& cloud, const SceneSegments& segments,
    const std::vector<std::size_t>& members, std::vector<FrameCandidate>& candidates,
    const SceneDepth& scene, const Eigen::Isometry3d& world_from_camera, std::optional<double> time,
    int* identifications, SceneUpdate* result, CandidateOutcome* union_outcome, int must_fit,
    std::optional<int> budget) {
  if (*identifications >= budget.value_or(parameters_.max_identifications)) {
    return UnionOutcome::kNotTried;
  }
  std::vector<const SceneCandidate*> parts;
  for (std::size_t m : members) parts.push_back(&segments.candidates[m]);
  SceneSegments whole;
  whole.planes = segments.planes;
  whole.candidates.push_back(mergedCandidate(cloud, parts));
  SceneUpdate merged;
  std::vector<FrameCandidate> union_candidate =
      frameCandidates(cloud, whole, world_from_camera, &merged);
  CandidateOutcome& outcome = merged.candidates.front();
  // A union no model fits is no identification (the groups of adjacentCandidateGroups mostly).
  const std::vector<int> fitting =
      library_.fitting(outcome.sides, parameters_.identification.extent_tolerance);
  if (fitting.empty() ||
      (must_fit >= 0 && std::find(fitting.begin(), fitting.end(), must_fit) == fitting.end())) {
    return UnionOutcome::kNotTried;
  }
  if (!unknowns_
           .notRetriedBecause(outcome.centroid_world, outcome.sides,
                              world_from_camera.translation(), union_candidate.front().points_world)
           .empty()) {
    return UnionOutcome::kNotTried;
  }
  ++*identifications;
  const int index =
      identify(union_candidate.front(), scene, world_from_camera, time, &outcome, false);
  if (union_outcome) *union_outcome = outcome;
  if (index < 0) return UnionOutcome::kUnknown;
  // The largest piece reports the instance, the others are its parts.
  for (std::size_t k = 0; k < members.size(); ++k) {
    candidates[members[k]].instance = index;
    CandidateOutcome& piece = result->candidates[members[k]];
    piece.instance = outcome.instance;
    if (k == 0) {
      piece.new_instance = outcome.new_instance;
      piece.moved = outcome.moved;
      piece.probability = outcome.probability;
      piece.update = outcome.update;
      // The union's own note first where it has one (a moved instance's, which the node logs).
      const std::string pieces =
          "with the " + std::to_string(members.size() - 1) + " piece(s) beside it";
      piece.note = outcome.note.empty() ? "identified " + pieces : outcome.note + ", " + pieces;
    } else {
      piece.note = "a part of " + instances_[index].name;
    }
  }
  return UnionOutcome::kIdentified;
}

int SceneEstimator::identify(const FrameCandidate& candidate, const SceneDepth& scene,
                             const Eigen::Isometry3d& world_from_camera, std::optional<double> time,
                             CandidateOutcome* outcome, bool remember_unknown,
                             const std::vector<const FrameCandidate*>& others) {
  // A detector's class is the evidence against an unknown simple shape: no penalty then.
  const std::vector<double> penalties =
      candidate.allowed.empty() ? shapes_->penalties(candidate.points, candidate.up, scene)
                                : std::vector<double>();
  SceneDepth candidate_scene = scene;
  candidate_scene.support_plane = candidate.support;
  Identification identification = identifyCandidate(
      library_, parameters_.instance, candidate.points, outcome->sides, candidate_scene,
      world_from_camera, time, parameters_.identification, penalties, candidate.allowed);
  if (identification.model >= 0 && !penalties.empty() && !others.empty()) {
    judgeShapesOnExplainedPieces(candidate, others, scene, penalties, &identification);
  }
  outcome->probability = identification.probability;
  if (identification.model < 0) {
    outcome->note = identification.reason;
    if (!candidate.allowed.empty()) outcome->note += " (only its class's model was tried)";
    if (!remember_unknown) return -1;
    unknowns_.remember(outcome->centroid_world, outcome->sides, world_from_camera.translation(),
                       candidate.points_world);
    return -1;
  }
  if (collidesWithLikelierInstance(identification, outcome)) {
    if (remember_unknown) {
      unknowns_.remember(outcome->centroid_world, outcome->sides, world_from_camera.translation(),
                         candidate.points_world);
    }
    return -1;
  }
  // A moved instance keeps its id; the fresh estimator that fused this view replaces its belief
  // (the object may have been turned on the way). So does an instance whose believed pose did
  // not explain this candidate while the identified pose shares its volume: its pose is out of
  // date, whether it moved a little or a piece fused this frame led it astray.
  const int same = sameObject(identification, outcome);
  if (same >= 0 && newOnThisFrame(instances_[same], time) &&
      instances_[same].identity_probability > identification.probability) {
    // A piece of an object found on this frame, identified less surely than the object was.
    outcome->moved = false;
    outcome->instance = instances_[same].id;
    outcome->note = "a part of " + instances_[same].name + ", which was identified more surely";
    return same;
  }
  const int index = same >= 0 ? same : instanceFor(identification.model, outcome);
  ObjectInstance& instance = instances_[index];
  instance.estimator = std::move(identification.estimator);
  instance.identity = identification.probabilities;
  instance.identity_probability = identification.probability;
  instance.centroid_world = outcome->centroid_world;
  instance.last_seen = time;
  ++instance.frames_seen;
  instance.presence = Presence{};
  outcome->instance = instance.id;
  outcome->update = identification.update;
  return index;
}

std::vector<const SceneEstimator::FrameCandidate*> SceneEstimator::unassignedBesides(
    const std::vector<FrameCandidate>& candidates, std::size_t candidate) {
  std::vector<const FrameCandidate*> others;
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    if (c != candidate && candidates[c].instance < 0 && !candidates[c].ignored) {
      others.push_back(&candidates[c]);
    }
  }
  return others;
}

void SceneEstimator::judgeShapesOnExplainedPieces(const FrameCandidate& candidate,
                                                  const std::vector<const FrameCandidate*>& others,
                                                  const SceneDepth& scene,
                                                  const std::vector<double>& penalties,
                                                  Identification* identification) const {
  const std::optional<Eigen::Isometry3d> pose = believedPose(*identification->estimator);
  if (!pose) return;
  std::vector<PieceView> pieces;
  for (const FrameCandidate* other : others)
    pieces.push_back({&other->points, &other->points_world});
  int joined = 0;
  const pcl::PointCloud<pcl::PointXYZ> object =
      withExplainedPieces(candidate.points, pieces, *explanations_[identification->model], *pose,
                          parameters_.part_tolerance, parameters_.min_explained_fraction, &joined);
  if (joined == 0) return;
  lowerPenalties(penalties, shapes_->penalties(object, candidate.up, scene),
                 parameters_.identification, identification);
}

bool SceneEstimator::newOnThisFrame(const ObjectInstance& instance, std::optional<double> time) {
  return time && instance.last_seen == time && instance.frames_seen == 1;
}

bool SceneEstimator::collidesWithLikelierInstance(const Identification& identification,
                                                  CandidateOutcome* outcome) {
  const std::optional<Eigen::Isometry3d> pose = believedPose(*identification.estimator);
  if (!pose) return false;
  const int rival = collision_->collidingInstance(instances_, identification.model, *pose,
                                                  kCollisionDepth, kMinCollision);
  if (rival < 0) return false;
  ObjectInstance& other = instances_[rival];
  if (other.identity_probability >= identification.probability) {
    outcome->note = library_.models()[identification.model].name + " would stand inside " +
                    other.name + ", which is at least as probable";
    return true;
  }
  // The less probable of the two yields; dropUnlikelyInstances forgets it at the end of the frame.
  outcome->note = "takes the place of " + other.name + ", which would stand inside it";
  other.identity_probability = 0.0;
  return false;
}

int SceneEstimator::sameObject(const Identification& identification,
                               CandidateOutcome* outcome) const {
  const std::optional<Eigen::Isometry3d> pose = believedPose(*identification.estimator);
  if (!pose) return -1;
  const int same =
      overlap_->overlappingInstance(instances_, identification.model, *pose, kSameObjectOverlap);
  if (same < 0) return -1;
  outcome->moved = true;
  outcome->note = instances_[same].name + " found off its believed place";
  return same;
}

int SceneEstimator::instanceFor(int model, CandidateOutcome* outcome) {
  const int moved = presence_->movedInstance(instances_, model, outcome->centroid_world);
  outcome->moved = moved >= 0;
  outcome->new_instance = moved < 0;
  if (moved >= 0) {
    outcome->note = instances_[moved].name + " moved here: its place was seen free";
    return moved;
  }
  ObjectInstance& added = instances_.emplace_back();
  added.id = next_id_++;
  added.model = model;
  added.name = library_.models()[model].name + "_" + std::to_string(++instances_named_[model]);
  return static_cast<int>(instances_.size()) - 1;
}

}  // namespace vdc
