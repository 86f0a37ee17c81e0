#include "view_direction_classification/refinement/pose_refiner.h"

#include <pcl/common/centroid.h>
#include <pcl/filters/voxel_grid.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <numeric>
#include <optional>
#include <sstream>
#include <string>
#include <unordered_map>
#include <utility>

#include "counted_voxels.h"
#include "fit_covariance.h"
#include "icp_alignment.h"
#include "kept_poses.h"
#include "roll_sector.h"
#include "shared_surfaces.h"
#include "start_screening.h"
#include "turned_starts.h"
#include "view_direction_classification/common/elapsed_time.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/parallel_for.h"
#include "view_direction_classification/common/quaternion.h"
#include "view_direction_classification/common/rotation_error.h"
#include "view_direction_classification/geometry/measured_point.h"
#include "visible_part.h"

namespace vdc {

namespace {

void checkPositive(double value, const char* name) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw Error(std::string("refinement's ") + name + " must be positive and finite, got " +
                std::to_string(value));
  }
}

void checkNonNegative(double value, const char* name) {
  if (!(value >= 0.0) || !std::isfinite(value)) {
    throw Error(std::string("refinement's ") + name + " must be >= 0 and finite, got " +
                std::to_string(value));
  }
}

void checkParameters(const RefinementParameters& p) {
  orientationHypotheses(BinghamMixture(), p.hypotheses);  // throws for invalid ones
  checkVerificationParameters(p.verification);
  checkPositive(p.model_spacing, "model_spacing");
  checkPositive(p.scene_voxel, "scene_voxel");
  checkPositive(p.max_extent_ratio, "max_extent_ratio");
  checkPositive(p.max_correspondence_distance, "max_correspondence_distance");
  checkPositive(p.max_translation_step, "max_translation_step");
  checkPositive(p.max_rotation_step_deg, "max_rotation_step_deg");
  checkPositive(p.convergence_translation, "convergence_translation");
  checkPositive(p.convergence_rotation_deg, "convergence_rotation_deg");
  checkPositive(p.max_log_density_drop, "max_log_density_drop");
  checkPositive(p.restart_max_log_density_drop, "restart_max_log_density_drop");
  checkPositive(p.restart_score_margin, "restart_score_margin");
  checkPositive(p.duplicate_angle_deg, "duplicate_angle_deg");
  checkPositive(p.duplicate_distance, "duplicate_distance");
  checkPositive(p.min_position_sigma, "min_position_sigma");
  checkPositive(p.max_position_sigma, "max_position_sigma");
  if (p.max_position_sigma < p.min_position_sigma) {
    throw Error("refinement's max_position_sigma must not be below min_position_sigma");
  }
  checkPositive(p.min_rotation_sigma_deg, "min_rotation_sigma_deg");
  checkPositive(p.max_rotation_sigma_deg, "max_rotation_sigma_deg");
  if (p.max_rotation_sigma_deg < p.min_rotation_sigma_deg) {
    throw Error("refinement's max_rotation_sigma_deg must not be below min_rotation_sigma_deg");
  }
  checkPositive(p.polish_correspondence_distance, "polish_correspondence_distance");
  checkPositive(p.polish_model_spacing, "polish_model_spacing");
  checkPositive(p.polish_scene_voxel, "polish_scene_voxel");
  checkNonNegative(p.polish_score_tolerance, "polish_score_tolerance");
  if (p.polish_iterations < 0) {
    throw Error("refinement's polish_iterations must be >= 0, got " +
                std::to_string(p.polish_iterations));
  }
  if (p.min_points < 3) {
    throw Error("refinement's min_points must be at least 3, got " + std::to_string(p.min_points));
  }
  if (p.piece_placements < 0) {
    throw Error("refinement's piece_placements must be >= 0, got " +
                std::to_string(p.piece_placements));
  }
  if (!(p.piece_spread_ratio >= 0.0) || !std::isfinite(p.piece_spread_ratio)) {
    throw Error("refinement's piece_spread_ratio must be a finite number >= 0, got " +
                std::to_string(p.piece_spread_ratio));
  }
  if (p.screening_points < 1) {
    throw Error("refinement's screening_points must be at least 1, got " +
                std::to_string(p.screening_points));
  }
  if (p.max_iterations < 1) {
    throw Error("refinement's max_iterations must be at least 1, got " +
                std::to_string(p.max_iterations));
  }
  if (!(p.continue_min_score >= -1.0 && p.continue_min_score <= 1.0)) {
    throw Error("refinement's continue_min_score must be in [-1, 1], got " +
                std::to_string(p.continue_min_score));
  }
  if (!(p.late_continue_min_score >= -1.0 && p.late_continue_min_score <= 1.0)) {
    throw Error("refinement's late_continue_min_score must be in [-1, 1], got " +
                std::to_string(p.late_continue_min_score));
  }
  if (!(p.restart_min_score >= -1.0 && p.restart_min_score <= 1.0)) {
    throw Error("refinement's restart_min_score must be in [-1, 1], got " +
                std::to_string(p.restart_min_score));
  }
  if (!(p.min_score >= -1.0 && p.min_score <= 1.0)) {
    throw Error("refinement's min_score must be in [-1, 1], got " + std::to_string(p.min_score));
  }
  if (p.restart_screening_iterations < 1) {
    throw Error("refinement's restart_screening_iterations must be at least 1, got " +
                std::to_string(p.restart_screening_iterations));
  }
  if (p.restart_rounds < 1 || p.restart_rounds > 2) {
    throw Error("refinement's restart_rounds must be 1 or 2, got " +
                std::to_string(p.restart_rounds));
  }
  if (p.restart_seeds < 0 || p.restart_refined < 1) {
    throw Error("refinement's restart_seeds must be >= 0 and restart_refined >= 1, got " +
                std::to_string(p.restart_seeds) + " and " + std::to_string(p.restart_refined));
  }
  if (!(p.restart_step_deg > 0.0 && p.restart_step_deg <= 180.0)) {
    throw Error("refinement's restart_step_deg must be in (0, 180], got " +
                std::to_string(p.restart_step_deg));
  }
  if (p.threads < 1) {
    throw Error("refinement's threads must be at least 1, got " + std::to_string(p.threads));
  }
  checkNonNegative(p.keep_score_margin, "keep_score_margin");
  checkNonNegative(p.measurement_score_margin, "measurement_score_margin");
  if (p.max_alternatives < 0) {
    throw Error("refinement's max_alternatives must be >= 0, got " +
                std::to_string(p.max_alternatives));
  }
}

// The measured points (geometry/measured_point.h) in front of every view's camera (their camera
// frames) and the same in the fixed frame.
struct Observation {
  std::vector<RefinementView> views;
  pcl::PointCloud<pcl::PointXYZ>::Ptr world{new pcl::PointCloud<pcl::PointXYZ>};
  // The first view's points in the fixed frame (the view starts are placed on and whose own fit
  // gives each kept pose's covariance): world itself for one view, or when the first has none.
  pcl::PointCloud<pcl::PointXYZ>::Ptr first;
};

Observation finitePoints(const std::vector<RefinementView>& views) {
  Observation observation;
  for (const RefinementView& view : views) {
    pcl::PointCloud<pcl::PointXYZ>::Ptr finite(new pcl::PointCloud<pcl::PointXYZ>);
    if (view.points) {
      for (const auto& p : view.points->points) {
        if (isMeasuredPoint(p) && p.z > 0.0f) {
          finite->push_back(p);
        }
      }
    }
    const Eigen::Isometry3f world_from_camera = view.world_from_camera.cast<float>();
    for (const auto& p : finite->points) {
      pcl::PointXYZ q;
      q.getVector3fMap() = world_from_camera * p.getVector3fMap();
      observation.world->push_back(q);
    }
    observation.views.push_back({finite, view.world_from_camera, view.scene});
  }
  const std::size_t first_count =
      observation.views.empty() ? 0 : observation.views[0].points->size();
  observation.first = observation.world;
  if (first_count > 0 && first_count < observation.world->size()) {
    observation.first.reset(new pcl::PointCloud<pcl::PointXYZ>);
    observation.first->points.assign(observation.world->begin(),
                                     observation.world->begin() + first_count);
    observation.first->width = static_cast<std::uint32_t>(first_count);
    observation.first->height = 1;
  }
  return observation;
}

// Empty when the input can be refined, else why not.
std::string badInputReason(const Observation& observation, const Eigen::Vector3d& position,
                           const std::vector<RefinementView>& views, const ModelSurface& surface,
                           const RefinementParameters& parameters) {
  for (const RefinementView& view : views) {
    if (!view.world_from_camera.matrix().allFinite()) return "a camera pose is not finite";
  }
  if (!position.allFinite()) return "the position estimate is not finite";
  const int count = static_cast<int>(observation.world->size());
  if (count < parameters.min_points) {
    return "only " + std::to_string(count) + " finite object points, refinement needs " +
           std::to_string(parameters.min_points);
  }
  Eigen::AlignedBox3d box;
  for (const auto& p : observation.world->points) box.extend(p.getVector3fMap().cast<double>());
  const double extent = box.diagonal().norm();
  if (extent > parameters.max_extent_ratio * surface.diagonal()) {
    std::ostringstream reason;
    reason.precision(3);
    reason << "the object points span " << extent << " m, more than " << parameters.max_extent_ratio
           << " times the model's " << surface.diagonal() << " m";
    return reason.str();
  }
  return "";
}

pcl::PointCloud<pcl::PointXYZ>::Ptr voxelFiltered(
    const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& points, double voxel) {
  pcl::VoxelGrid<pcl::PointXYZ> grid;
  grid.setInputCloud(points);
  const float leaf = static_cast<float>(voxel);
  grid.setLeafSize(leaf, leaf, leaf);
  pcl::PointCloud<pcl::PointXYZ>::Ptr filtered(new pcl::PointCloud<pcl::PointXYZ>);
  grid.filter(*filtered);
  return filtered;
}

// Each view's points thinned to the voxel: a 640 x 480 view of the mug has ~10 000, which would
// make every score cost ten times more without changing it.
std::vector<RefinementView> thinnedViews(const std::vector<RefinementView>& views, double voxel) {
  std::vector<RefinementView> thinned;
  for (const RefinementView& view : views) {
    if (view.points->empty()) continue;
    thinned.push_back(thinnedView(view, voxel));
  }
  return thinned;
}

pcl::PointCloud<pcl::PointNormal>::Ptr icpSource(const pcl::PointCloud<pcl::PointXYZ>& filtered) {
  pcl::PointCloud<pcl::PointNormal>::Ptr source(new pcl::PointCloud<pcl::PointNormal>);
  for (const auto& p : filtered.points) {
    pcl::PointNormal point;
    point.getVector3fMap() = p.getVector3fMap();
    point.getNormalVector3fMap().setZero();
    source->push_back(point);
  }
  return source;
}

// The poses of orientation q that put the centroid of the model's part the first camera sees
// (from where the position estimate is), and for a piece the centroids of patches of that part
// (visible_part.h), onto the observed centroid. The estimator's position comes from the MAP's
// centroid offset; for another roll the visible part, and so the offset, differ by up to the
// object's size, more than ICP's correspondence distance.
std::vector<Eigen::Isometry3d> placedHypotheses(const Eigen::Vector4d& q,
                                                const Eigen::Vector3d& position,
                                                const Eigen::Vector3d& observed_centroid,
                                                const Eigen::Vector3d& camera_position,
                                                VisibleParts* visible) {
  const Eigen::Matrix3d rotation = quaternionToRotationMatrix(q);
  const Eigen::Vector3d camera = rotation.transpose() * (camera_position - position);
  // Where no sample faces the camera (it would sit inside the model) there is no anchor and so
  // no start; before pieces were placed such a start went to the observed centroid. Restoring
  // that changed one instance's cone90 on the scene evaluation, so the figures recorded are for
  // this rule.
  std::vector<Eigen::Isometry3d> poses;
  for (const Eigen::Vector3d& anchor : visible->anchors(camera)) {
    Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
    pose.linear() = rotation;
    pose.translation() = observed_centroid - rotation * anchor;
    poses.push_back(pose);
  }
  return poses;
}

Eigen::Vector4d orientationOf(const Eigen::Isometry3d& pose) {
  Eigen::Vector4d q = quaternionFromRotationMatrix(pose.linear());
  return q(0) < 0.0 ? Eigen::Vector4d(-q) : q;
}

// The belief's starts (pose_hypotheses.h), each placed where the first camera sees the observed
// centroid and screened by its mean truncated distance to the screening points.
std::vector<RefinedPose> placedStarts(const BinghamMixture& belief, const Eigen::Vector3d& position,
                                      const Eigen::Vector3d& observed_centroid,
                                      const Eigen::Vector3d& camera_position,
                                      const ModelSurface& surface,
                                      const pcl::PointCloud<pcl::PointXYZ>& screening_points,
                                      const RefinementParameters& parameters) {
  std::vector<Eigen::Vector3d> observed;
  for (const auto& p : screening_points) observed.push_back(p.getVector3fMap().cast<double>());
  VisibleParts visible(surface, rmsRadius(observed), parameters.piece_spread_ratio,
                       parameters.piece_placements);
  std::vector<RefinedPose> starts;
  for (const OrientationStart& start : orientationHypotheses(belief, parameters.hypotheses)) {
    RefinedPose pose;
    pose.start_orientation =
        start.orientation(0) < 0 ? Eigen::Vector4d(-start.orientation) : start.orientation;
    pose.component = start.component;
    pose.orientation = pose.start_orientation;
    pose.rejection = std::string("screened out: its start fits worse than ") +
                     (parameters.screen_per_component ? "its component's " : "the ") +
                     std::to_string(parameters.max_refined) + " best";
    for (const Eigen::Isometry3d& placed : placedHypotheses(
             pose.start_orientation, position, observed_centroid, camera_position, &visible)) {
      pose.start = placed;
      pose.world_from_object = placed;
      starts.push_back(pose);
    }
  }
  // A first view's two girdles place dozens of starts; each screening is a batched search.
  parallelFor(starts.size(), parameters.threads, [&](int, std::size_t i) {
    starts[i].screening_distance = meanTruncatedDistance(surface, screening_points, starts[i].start,
                                                         parameters.max_correspondence_distance);
  });
  return starts;
}

// Empty when the refined pose is accepted, else why not. reference: the belief's orientation the
// pose's chain of starts began from, whose density the result must stay near.
std::string rejection(const RefinedPose& pose, const IcpOutcome& icp, const BinghamMixture& belief,
                      const Eigen::Vector4d& reference, const RefinementParameters& parameters) {
  if (icp.degenerate) return "ICP was degenerate: the points leave a motion unconstrained";
  if (icp.too_few_pairs) {
    return "ICP found too few point pairs within max_correspondence_distance";
  }
  if (!icp.converged) return "ICP did not converge";
  const double moved = (pose.world_from_object.translation() - pose.start.translation()).norm();
  const double turned = rotationErrorDeg(pose.orientation, pose.start_orientation);
  if (moved > parameters.max_translation_step || turned > parameters.max_rotation_step_deg) {
    return "ICP diverged: it moved the pose by " + std::to_string(moved * 1000.0) + " mm and " +
           std::to_string(turned) + " deg";
  }
  // Within keep_score_margin poses are equally good: a start that verified well already (a
  // converged pose turned half a turn onto its equivalent) loses a few thousandths to ICP's
  // settling as often as it gains them.
  if (pose.score.score() < pose.start_score.score() - parameters.keep_score_margin) {
    return "ICP made the verification worse";
  }
  if (pose.score.score() < parameters.min_score) {
    return "verification score " + std::to_string(pose.score.score()) + " is below " +
           std::to_string(parameters.min_score);
  }
  if (belief.logDensity(pose.orientation) <
      belief.logDensity(reference) - parameters.max_log_density_drop) {
    return "the refined orientation left the belief's credible region";
  }
  return "";
}

// The kept poses with their roll sectors (roll_sector.h), best first; a pose on a better one's
// sector is that pose again, turned, and is dropped.
std::vector<RefinedPose> withRollSectors(std::vector<RefinedPose> kept, const ModelSurface& surface,
                                         const PoseVerifier& verifier,
                                         const RefinementParameters& parameters) {
  // Every pose's sector in parallel (a first view keeps two), then the turned ones dropped.
  if (!surface.symmetryAxes().empty()) {
    parallelFor(kept.size(), parameters.threads, [&](int, std::size_t i) {
      kept[i].sector_axis = surface.symmetryAxes().front().direction();
      kept[i].roll_sector_deg = verifiedRollSectorDeg(
          surface, verifier, kept[i], parameters.restart_step_deg, parameters.keep_score_margin);
    });
  }
  std::vector<RefinedPose> distinct;
  for (const RefinedPose& pose : kept) {
    if (!onARollSectorOf(pose, distinct, parameters)) distinct.push_back(pose);
  }
  return distinct;
}

// The samples of `surface` that face one of the cameras (object frame) at least a little, or
// null when fewer than 10 do: what the polish may match a point to. A point on a thin wall's
// outside otherwise pairs with the inside's samples a few millimetres behind it.
std::shared_ptr<const ModelSurface> facingPart(const ModelSurface& surface,
                                               const std::vector<Eigen::Vector3f>& cameras) {
  std::vector<Eigen::Vector3f> points, normals;
  for (const auto& sample : surface.cloud()->points) {
    const Eigen::Vector3f p = sample.getVector3fMap();
    const Eigen::Vector3f n = sample.getNormalVector3fMap();
    const bool facing = std::any_of(cameras.begin(), cameras.end(),
                                    [&](const Eigen::Vector3f& c) { return n.dot(c - p) > 0.0f; });
    if (!facing) continue;
    points.push_back(p);
    normals.push_back(n);
  }
  if (points.size() < 10) return nullptr;
  return std::make_shared<const ModelSurface>(points, normals, surface.bounds(), surface.spacing(),
                                              surface.spacing());
}

// Each kept pose aligned once more, on every observed point (voxel-filtered to
// polish_scene_voxel, each centroid weighted by the points it stands for, so that the fit weighs
// the surface as all the points would) against the finer polish surface, with tighter
// correspondences: the starts' ICP runs on a few hundred points against 4 mm samples and settles
// within half a millimetre and a degree, which leaves a floor of a few tenths of a degree
// (doc/method.md, "Refinement").
void polishKept(const ModelSurface& surface, const CountedVoxels& observed,
                const std::vector<RefinementView>& views, const PoseVerifier& verifier,
                const RefinementParameters& parameters, std::vector<RefinedPose>* kept) {
  IcpSettings settings;
  settings.max_iterations = parameters.polish_iterations;
  settings.max_correspondence_distance = parameters.polish_correspondence_distance;
  settings.convergence_translation = 0.1 * parameters.convergence_translation;
  settings.convergence_rotation_deg = 0.1 * parameters.convergence_rotation_deg;
  settings.settle_iterations = parameters.polish_iterations;  // PCL's criteria alone
  const auto source = icpSource(*observed.centroids);
  // Each pose's facing samples and ICP are its own, and the verifier is thread-safe: the poses
  // are polished in parallel (a first view keeps two).
  parallelFor(kept->size(), parameters.threads, [&](int, std::size_t index) {
    RefinedPose& pose = (*kept)[index];
    const Eigen::Isometry3d object_from_world = pose.world_from_object.inverse();
    std::vector<Eigen::Vector3f> cameras;
    for (const RefinementView& view : views) {
      cameras.push_back((object_from_world * view.world_from_camera.translation()).cast<float>());
    }
    const std::shared_ptr<const ModelSurface> facing = facingPart(surface, cameras);
    if (!facing) return;
    const IcpOutcome outcome =
        IcpAlignment(facing, source, settings, observed.counts).align(object_from_world);
    if (!outcome.converged) return;
    RefinedPose polished = pose;
    polished.world_from_object = outcome.object_from_world.inverse();
    polished.orientation = orientationOf(polished.world_from_object);
    polished.score = verifier.score(polished.world_from_object);
    if (samePose(polished, pose, parameters) &&
        polished.score.score() >= pose.score.score() - parameters.polish_score_tolerance) {
      pose = polished;
    }
  });
}

// Why a start's ICP was abandoned after `iterations`.
std::string abandonment(int iterations, double score, const char* threshold_name,
                        double threshold) {
  std::ostringstream reason;
  reason.precision(3);
  reason << "abandoned: after " << iterations << " ICP iterations it verifies " << score
         << ", below " << threshold_name << " " << threshold;
  return reason.str();
}

// What aligning and verifying a start takes: the same for the belief's starts and restarts. One
// ICP per worker thread (an IcpAlignment is not thread-safe; the verifier and the belief are).
struct Aligner {
  std::vector<std::unique_ptr<IcpAlignment>> icps;
  const PoseVerifier* verifier;
  const BinghamMixture* belief;
  const RefinementParameters* parameters;

  int workers() const { return static_cast<int>(icps.size()); }

  // Aligns *pose from its start (whose start_score is set) with worker's ICP and verifies the
  // result; an ICP still far from fitting after the screening iterations is abandoned there.
  void alignAndVerify(int worker, const Eigen::Vector4d& reference, RefinedPose* pose) const {
    const int screening =
        std::min(parameters->restart_screening_iterations, parameters->max_iterations);
    const IcpOutcome first = icps[worker]->align(pose->start.inverse(), screening);
    if (first.ended() || screening == parameters->max_iterations) {
      record(first, std::nullopt, reference, pose);
      return;
    }
    if (abandoned(first, "continue_min_score", parameters->continue_min_score, reference, pose)) {
      return;
    }
    alignRest(worker, first, reference, pose);
  }

  // Aligns *pose on from `first`, a short alignment of its start that has not ended, to the end
  // of a full ICP (max_iterations in all: the same iterations as one from the start), screened
  // once more after late_screening_iterations, verifies the result and judges it.
  void alignRest(int worker, const IcpOutcome& first, const Eigen::Vector4d& reference,
                 RefinedPose* pose) const {
    IcpOutcome rest = first;
    const int late = std::min(parameters->late_screening_iterations, parameters->max_iterations);
    if (late > rest.iterations) {
      rest = alignFurther(worker, rest, late);
      if (!rest.ended() && rest.iterations < parameters->max_iterations &&
          abandoned(rest, "late_continue_min_score", parameters->late_continue_min_score, reference,
                    pose)) {
        return;
      }
    }
    if (!rest.ended()) rest = alignFurther(worker, rest, parameters->max_iterations);
    record(rest, std::nullopt, reference, pose);
  }

  // Whether an ICP not ended at `so_far` verifies there below `min_score`: then *pose is
  // recorded there as abandoned, naming the threshold.
  bool abandoned(const IcpOutcome& so_far, const char* threshold_name, double min_score,
                 const Eigen::Vector4d& reference, RefinedPose* pose) const {
    const double screened = verifier->score(so_far.object_from_world.inverse()).score();
    if (screened >= min_score) return false;
    record(so_far, std::nullopt, reference, pose);
    pose->rejection = abandonment(so_far.iterations, screened, threshold_name, min_score);
    return true;
  }

  // ICP on from `so_far` (not ended) until `iterations` in all. In chunks that begin where the
  // last ended, ICP takes the same path as in one run (IcpAlignment::align).
  IcpOutcome alignFurther(int worker, const IcpOutcome& so_far, int iterations) const {
    IcpOutcome further =
        icps[worker]->align(so_far.object_from_world, iterations - so_far.iterations);
    further.iterations += so_far.iterations;
    return further;
  }

  // Sets *pose from ICP's outcome and verifies it (unless its score is known) and judges it.
  void record(const IcpOutcome& outcome, const std::optional<VerificationScore>& known_score,
              const Eigen::Vector4d& reference, RefinedPose* pose) const {
    pose->screened_in = true;
    pose->converged = outcome.converged;
    pose->world_from_object = outcome.converged ? outcome.object_from_world.inverse() : pose->start;
    pose->orientation = orientationOf(pose->world_from_object);
    pose->fitness = outcome.fitness;
    pose->icp_iterations = outcome.iterations;
    if (outcome.converged) {
      pose->score = known_score ? *known_score : verifier->score(pose->world_from_object);
    }
    pose->rejection = rejection(*pose, outcome, *belief, reference, *parameters);
    pose->accepted = pose->rejection.empty();
  }

  // Sets the start score of each pose at `indices` and aligns and verifies it, in parallel.
  void alignAll(const std::vector<std::size_t>& indices, std::vector<RefinedPose>* poses,
                const std::function<Eigen::Vector4d(const RefinedPose&)>& reference) const {
    parallelFor(indices.size(), workers(), [&](int worker, std::size_t i) {
      RefinedPose& pose = (*poses)[indices[i]];
      pose.start_score = verifier->score(pose.start);
      alignAndVerify(worker, reference(pose), &pose);
    });
  }
};

// Indices of the `count` best-scoring distinct converged poses verifying at least
// restart_min_score, best first.
std::vector<std::size_t> restartSeeds(const std::vector<RefinedPose>& tried, int count,
                                      const RefinementParameters& parameters) {
  std::vector<std::size_t> converged;
  for (std::size_t i = 0; i < tried.size(); ++i) {
    if (tried[i].converged && tried[i].score.score() >= parameters.restart_min_score) {
      converged.push_back(i);
    }
  }
  std::stable_sort(converged.begin(), converged.end(), [&](std::size_t a, std::size_t b) {
    return tried[a].score.score() > tried[b].score.score();
  });
  std::vector<std::size_t> seeds;
  for (const std::size_t index : converged) {
    if (static_cast<int>(seeds.size()) >= count) break;
    const bool duplicate = std::any_of(seeds.begin(), seeds.end(), [&](std::size_t seed) {
      return samePose(tried[index], tried[seed], parameters);
    });
    if (!duplicate) seeds.push_back(index);
  }
  return seeds;
}

// The seed's turns about the model's symmetry axes (turned_starts.h) that the belief still allows:
// a turn it finds more than restart_max_log_density_drop less likely than the seed's start could
// only be accepted if ICP carried it back into the credible region, i.e. onto the seed again. On a
// first view the belief's girdles allow every turn; once verified poses have made it sharp (from
// about the third view) none, and the restart costs nothing.
std::vector<RefinedPose> allowedTurns(const RefinedPose& seed, std::size_t seed_index,
                                      const ModelSurface& surface, const BinghamMixture& belief,
                                      const RefinementParameters& parameters,
                                      bool half_turns_only) {
  const double least_log_density =
      belief.logDensity(seed.start_orientation) - parameters.restart_max_log_density_drop;
  std::vector<RefinedPose> turned;
  for (const Eigen::Isometry3d& start :
       half_turns_only
           ? halfTurnStarts(surface, seed.world_from_object)
           : turnedStarts(surface, seed.world_from_object, parameters.restart_step_deg)) {
    RefinedPose pose;
    pose.start = pose.world_from_object = start;
    pose.start_orientation = pose.orientation = orientationOf(start);
    if (belief.logDensity(pose.start_orientation) < least_log_density) continue;
    pose.component = seed.component;
    pose.restarted_from = static_cast<int>(seed_index);
    pose.rejection = "screened out: after " +
                     std::to_string(parameters.restart_screening_iterations) +
                     " ICP iterations it verifies worse than its seed's " +
                     std::to_string(parameters.restart_refined) + " best turns";
    turned.push_back(pose);
  }
  return turned;
}

// The seed turned about the model's symmetry axes where the belief allows it, each turn screened
// by a short ICP and verified; the restart_refined best continue from there to the end of a full
// ICP (the same iterations as one from the turn) and are judged like any start. Appended to
// *tried. half_turns_only: the two half turns, not the turns about the axis of near symmetry.
void restartFrom(std::size_t seed_index, const ModelSurface& surface, const Aligner& aligner,
                 std::vector<RefinedPose>* tried, bool half_turns_only = false) {
  const RefinedPose seed = (*tried)[seed_index];
  const RefinementParameters& parameters = *aligner.parameters;
  std::vector<RefinedPose> turned =
      allowedTurns(seed, seed_index, surface, *aligner.belief, parameters, half_turns_only);
  std::vector<IcpOutcome> screened(turned.size());
  std::vector<VerificationScore> screening_scores(turned.size());
  parallelFor(turned.size(), aligner.workers(), [&](int worker, std::size_t i) {
    screened[i] = aligner.icps[worker]->align(turned[i].start.inverse(),
                                              parameters.restart_screening_iterations);
    if (!screened[i].degenerate) {
      screening_scores[i] = aligner.verifier->score(screened[i].object_from_world.inverse());
    }
  });
  const auto screening_score = [&](std::size_t i) {
    return screened[i].degenerate ? -1.0 : screening_scores[i].score();
  };
  std::vector<std::size_t> order(turned.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return screening_score(a) > screening_score(b);
  });
  order.resize(std::min(order.size(), static_cast<std::size_t>(parameters.restart_refined)));
  // A turn still verifying restart_score_margin below its seed after the short ICP fits the body
  // another way, not the seed's handle turned right: ICP crawls on from there (91 iterations on
  // the benchmark's first view) to a pose the belief refuses.
  const double least_score = seed.score.score() - parameters.restart_score_margin;
  order.erase(std::remove_if(order.begin(), order.end(),
                             [&](std::size_t i) { return screening_score(i) < least_score; }),
              order.end());
  parallelFor(order.size(), aligner.workers(), [&](int worker, std::size_t k) {
    const std::size_t i = order[k];
    RefinedPose& pose = turned[i];
    pose.start_score = aligner.verifier->score(pose.start);
    const IcpOutcome& first = screened[i];
    if (first.ended()) {
      aligner.record(first, screening_scores[i], seed.start_orientation, &pose);
      return;
    }
    aligner.alignRest(worker, first, seed.start_orientation, &pose);
  });
  tried->insert(tried->end(), turned.begin(), turned.end());
}

// One more round of restarts, its half turns only, when a restart beat every seed: that pose is
// converged and no restart has turned it. On a view a half turn cannot tell (the mug seen around
// its handle) the seed fitted the truth a few degrees off, its half turn landed on the twin
// exactly, and only the twin's own half turn lands on the truth exactly: without it the
// measurement holds the twin alone, sharper than the view. Its turns about the axis of near
// symmetry as well reached a mirrored handle's local fit that verified 0.83 (the pose
// refiner's test of the mirrored handle).
void restartTheBestRestart(const ModelSurface& surface, const Aligner& aligner,
                           std::vector<RefinedPose>* tried) {
  const RefinementParameters& parameters = *aligner.parameters;
  if (parameters.restart_seeds <= 0 || parameters.restart_rounds < 2) return;
  const std::vector<std::size_t> best = restartSeeds(*tried, 1, parameters);
  if (best.empty() || (*tried)[best.front()].restarted_from < 0) return;
  restartFrom(best.front(), surface, aligner, tried, /*half_turns_only=*/true);
}

}  // namespace

// The scene is kept whole: the verifier indexes only its points around the object.
RefinementView thinnedView(const RefinementView& view, double voxel) {
  return {voxelFiltered(view.points, voxel), view.world_from_camera, view.scene};
}

PoseRefiner::PoseRefiner(std::shared_ptr<const ModelSurface> surface,
                         RefinementParameters parameters)
    : surface_(std::move(surface)), polish_surface_(surface_), parameters_(parameters) {
  if (!surface_) throw Error("the pose refiner needs a model surface");
  checkParameters(parameters_);
}

PoseRefiner::PoseRefiner(const ModelBundle& model, RefinementParameters parameters)
    : PoseRefiner(sharedModelSurface(model, parameters.model_spacing), parameters) {
  // The bundle's samples at polish_model_spacing (its own spacing, 2 mm by default, when that is
  // coarser): the polish's target. Without a polish, or at the same spacing, it is surface_.
  if (parameters_.polish_iterations > 0 &&
      parameters_.polish_model_spacing != parameters_.model_spacing) {
    polish_surface_ = sharedModelSurface(model, parameters_.polish_model_spacing);
  }
}

PoseRefiner::PoseRefiner(const PoseRefiner& other, RefinementParameters parameters)
    : surface_(other.surface_), polish_surface_(other.polish_surface_), parameters_(parameters) {
  checkParameters(parameters_);
  const bool polish_surface_differs =
      parameters_.polish_iterations > 0 &&
      (other.parameters_.polish_iterations <= 0 ||
       parameters_.polish_model_spacing != other.parameters_.polish_model_spacing);
  if (parameters_.model_spacing != other.parameters_.model_spacing || polish_surface_differs) {
    throw Error("a refiner sharing another's surfaces needs its model and polish spacings");
  }
}

RefinementResult PoseRefiner::refine(const BinghamMixture& belief, const Eigen::Vector3d& position,
                                     const std::vector<RefinementView>& views) const {
  const auto start_time = std::chrono::steady_clock::now();
  RefinementResult result;
  const Observation observation = finitePoints(views);
  result.skip_reason = badInputReason(observation, position, views, *surface_, parameters_);
  if (result.skipped()) return result;

  // Starts are placed on the first view (the one just fused): its camera saw the centroid.
  Eigen::Vector4f centroid;
  pcl::compute3DCentroid(*observation.first, centroid);
  const Eigen::Vector3d observed_centroid = centroid.head<3>().cast<double>();
  const Eigen::Vector3d camera_position = observation.views.front().world_from_camera.translation();
  const pcl::PointCloud<pcl::PointXYZ>::Ptr thinned =
      voxelFiltered(observation.world, parameters_.scene_voxel);
  // Each kept pose's covariances come from the first view's own fit: earlier views were fused
  // with theirs already, and counting their points again would make the belief overconfident.
  const pcl::PointCloud<pcl::PointXYZ>::Ptr thinned_first =
      observation.first == observation.world
          ? thinned
          : voxelFiltered(observation.first, parameters_.scene_voxel);
  const pcl::PointCloud<pcl::PointXYZ>::Ptr screening_points =
      evenSubsample(*thinned, parameters_.screening_points);

  result.tried = placedStarts(belief, position, observed_centroid, camera_position, *surface_,
                              *screening_points, parameters_);
  std::vector<double> distances;
  std::vector<int> components;
  for (const RefinedPose& pose : result.tried) {
    distances.push_back(pose.screening_distance);
    components.push_back(parameters_.screen_per_component ? pose.component : 0);
  }

  const PoseVerifier verifier(surface_, thinnedViews(observation.views, parameters_.scene_voxel),
                              parameters_.verification);
  Aligner aligner{{}, &verifier, &belief, &parameters_};
  const auto source = icpSource(*evenSubsample(*thinned, parameters_.icp_points));
  const IcpSettings settings{parameters_.max_iterations, parameters_.max_correspondence_distance,
                             parameters_.convergence_translation,
                             parameters_.convergence_rotation_deg};
  for (int worker = 0; worker < parameters_.threads; ++worker) {
    aligner.icps.push_back(std::make_unique<IcpAlignment>(surface_, source, settings));
  }
  aligner.alignAll(bestStarts(distances, components, parameters_.max_refined), &result.tried,
                   [](const RefinedPose& pose) { return pose.start_orientation; });
  for (const std::size_t seed :
       restartSeeds(result.tried, parameters_.restart_seeds, parameters_)) {
    restartFrom(seed, *surface_, aligner, &result.tried);
  }
  restartTheBestRestart(*surface_, aligner, &result.tried);
  result.kept = keptPoses(result.tried, parameters_);
  if (parameters_.polish_iterations > 0) {
    polishKept(*polish_surface_, countedVoxels(observation.world, parameters_.polish_scene_voxel),
               observation.views, verifier, parameters_, &result.kept);
  }
  if (parameters_.roll_sectors)
    result.kept = withRollSectors(std::move(result.kept), *surface_, verifier, parameters_);
  result.alternatives = verifiedAlternatives(result.tried, result.kept, parameters_);
  const CovarianceBounds bounds{parameters_.min_position_sigma, parameters_.max_position_sigma,
                                parameters_.min_rotation_sigma_deg * M_PI / 180.0,
                                parameters_.max_rotation_sigma_deg * M_PI / 180.0};
  for (RefinedPose& pose : result.kept) {
    const FitCovariance covariance =
        fitCovariance(*surface_, *thinned_first, pose.world_from_object,
                      parameters_.max_correspondence_distance, bounds);
    pose.position_covariance = covariance.translation;
    pose.rotation_covariance = covariance.rotation;
  }
  result.milliseconds = millisecondsSince(start_time);
  return result;
}

const RefinedPose* bestFittedPose(const RefinementResult& refinement) {
  const RefinedPose* best = nullptr;
  for (const RefinedPose& pose : refinement.tried) {
    if (!pose.screened_in || !pose.converged || pose.score.observed == 0) continue;
    if (!best || pose.score.identityScore() > best->score.identityScore()) best = &pose;
  }
  return best;
}

std::optional<double> bestFittedIdentityScore(const RefinementResult& refinement) {
  const RefinedPose* best = bestFittedPose(refinement);
  if (!best) return std::nullopt;
  return best->score.identityScore();
}

}  // namespace vdc
