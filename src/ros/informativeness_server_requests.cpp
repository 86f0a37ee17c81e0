#include "informativeness_server_requests.h"

#include <geometry_msgs/Pose.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl_conversions/pcl_conversions.h>
#include <ros/time.h>
#include <tf2_eigen/tf2_eigen.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/quaternion.h"
#include "view_direction_classification/ros/bingham_conversions.h"
#include "view_direction_classification/ros/cloud_conversions.h"
#include "view_direction_classification/visualisation/heatmap_colours.h"

namespace vdc {
namespace {

using view_direction_classification::GetHeatmap;
using view_direction_classification::GetNextBestView;

constexpr const char* kNoSingleModel =
    "This server has no single model (~model unset, only ~models): name an instance (or "
    "\"most_uncertain\") in `instance`.";

double minimumOfValid(const Eigen::VectorXf& values) {
  double minimum = 0.0;
  bool any = false;
  for (Eigen::Index i = 0; i < values.size(); ++i) {
    if (!(values(i) >= 0.0f)) continue;
    minimum = any ? std::min(minimum, double(values(i))) : double(values(i));
    any = true;
  }
  return minimum;
}

geometry_msgs::Pose toPoseMsg(const Eigen::Isometry3d& pose) { return tf2::toMsg(pose); }

Eigen::Isometry3d fromPoseMsg(const geometry_msgs::Pose& msg, std::size_t index) {
  const Eigen::Vector3d position(msg.position.x, msg.position.y, msg.position.z);
  const Eigen::Vector4d rotation(msg.orientation.w, msg.orientation.x, msg.orientation.y,
                                 msg.orientation.z);
  if (!position.allFinite() || !isUnitQuaternion(rotation, kRequestQuaternionTolerance)) {
    throw Error("Candidate pose " + std::to_string(index) +
                " has a non-finite position or a non-unit orientation.");
  }
  Eigen::Isometry3d pose;
  tf2::fromMsg(msg, pose);
  return pose;
}

// An instance's pose from ~instances (fixed frame); throws vdc::Error for a broken one.
Eigen::Isometry3d instancePose(const ObjectInstanceMsg& instance) {
  const geometry_msgs::Pose& msg = instance.pose.pose;
  const Eigen::Vector3d position(msg.position.x, msg.position.y, msg.position.z);
  const Eigen::Vector4d rotation(msg.orientation.w, msg.orientation.x, msg.orientation.y,
                                 msg.orientation.z);
  if (!position.allFinite() || !isUnitQuaternion(rotation, kRequestQuaternionTolerance)) {
    throw Error("Instance '" + instance.name +
                "' has a non-finite position or a non-unit orientation in the latest instances.");
  }
  Eigen::Isometry3d pose;
  tf2::fromMsg(msg, pose);
  return pose;
}

}  // namespace

sensor_msgs::PointCloud2 colouredSurface(const ModelBundle& model, const Eigen::VectorXf& scores,
                                         double black_at, const std::string& frame) {
  pcl::PointCloud<pcl::PointXYZRGB> cloud;
  cloud.reserve(model.surface_points.size());
  for (std::size_t i = 0; i < model.surface_points.size(); ++i) {
    const auto rgb = heatmapColour(scores(static_cast<Eigen::Index>(i)), black_at);
    pcl::PointXYZRGB point(rgb[0], rgb[1], rgb[2]);
    point.x = model.surface_points[i].x();
    point.y = model.surface_points[i].y();
    point.z = model.surface_points[i].z();
    cloud.push_back(point);
  }
  sensor_msgs::PointCloud2 msg;
  pcl::toROSMsg(cloud, msg);
  msg.header.frame_id = frame;
  msg.header.stamp = ros::Time(0);  // static in the object frame: rviz uses the latest tf
  return msg;
}

InformativenessServerRequests::InformativenessServerRequests(
    std::shared_ptr<const ModelBundle> model, InformativenessServerRosParameters parameters,
    FrameLookup lookup, const ServedLibrary& library)
    : model_(std::move(model)),
      scorer_(model_ ? std::make_unique<ViewUtilityScorer>(model_) : nullptr),
      lookup_(std::move(lookup)),
      parameters_(std::move(parameters)) {
  if (!model_ && library.empty()) throw Error("The server has neither a model nor a library.");
  for (const auto& [name, bundle] : library) {
    library_[name] = std::make_unique<ViewUtilityScorer>(bundle);
  }
}

void InformativenessServerRequests::setParameters(
    const InformativenessServerRosParameters& parameters) {
  std::lock_guard<std::mutex> lock(parameters_mutex_);
  parameters_ = parameters;
}

InformativenessServerRosParameters InformativenessServerRequests::parameters() const {
  std::lock_guard<std::mutex> lock(parameters_mutex_);
  return parameters_;
}

Eigen::Isometry3d InformativenessServerRequests::lookupFixedFrom(const std::string& frame,
                                                                 const std::string& fixed_frame,
                                                                 const char* what) const {
  if (frame.empty() || frame == fixed_frame) return Eigen::Isometry3d::Identity();
  return lookup_(frame, what);
}

void InformativenessServerRequests::receiveEstimate(
    const view_direction_classification::BinghamMixture& msg) {
  const std::string fixed_frame = parameters().fixed_frame;
  if (!msg.header.frame_id.empty() && msg.header.frame_id != fixed_frame) {
    throw Error("it is in frame '" + msg.header.frame_id + "', not the fixed frame '" +
                fixed_frame + "'");
  }
  BinghamMixture belief = fromBinghamMixtureMsg(msg);
  const Eigen::Vector4d map = mapEstimate(belief);
  std::lock_guard<std::mutex> lock(belief_mutex_);
  latest_belief_ = std::move(belief);
  latest_map_ = map;
}

void InformativenessServerRequests::receiveInstances(const ObjectInstancesMsg& msg) {
  const std::string fixed_frame = parameters().fixed_frame;
  if (!msg.header.frame_id.empty() && msg.header.frame_id != fixed_frame) {
    throw Error("they are in frame '" + msg.header.frame_id + "', not the fixed frame '" +
                fixed_frame + "'");
  }
  instances_.keep(msg);
}

ObjectInstanceMsg InformativenessServerRequests::chosenInstance(const std::string& wanted) const {
  if (library_.empty()) {
    throw Error(
        "This server has no model library (~models), so it plans for its one object "
        "only: leave `instance` empty.");
  }
  return instances_.choose(wanted);
}

const ViewUtilityScorer& InformativenessServerRequests::libraryScorer(
    const ObjectInstanceMsg& instance) const {
  const auto found = library_.find(instance.model);
  if (found == library_.end()) {
    std::string loaded;
    for (const auto& entry : library_) loaded += (loaded.empty() ? "" : ", ") + entry.first;
    throw Error("Instance '" + instance.name + "' is a '" + instance.model +
                "', a model this server has not loaded (its ~models: " + loaded + ").");
  }
  return *found->second;
}

void InformativenessServerRequests::getHeatmap(const GetHeatmap::Request& request,
                                               GetHeatmap::Response& response) const {
  try {
    answerHeatmap(request, response);
    response.success = true;
  } catch (const std::exception& error) {
    response = GetHeatmap::Response();
    response.success = false;
    response.message = error.what();
  }
}

void InformativenessServerRequests::answerHeatmap(const GetHeatmap::Request& request,
                                                  GetHeatmap::Response& response) const {
  // The one model in object_frame, or the named instance's model in its own tf frame.
  std::string frame = parameters().object_frame;
  const ViewUtilityScorer* scorer = scorer_.get();
  std::string whose;
  if (!request.instance.empty()) {
    const ObjectInstanceMsg instance = chosenInstance(request.instance);
    scorer = &libraryScorer(instance);
    frame = instance.name;
    whose = " Instance " + instance.name + " (model " + instance.model + ").";
  } else if (scorer == nullptr) {
    throw Error(kNoSingleModel);
  }
  const ModelBundle& model = scorer->model();
  const int views = scorer->viewCount();
  int view = -1;
  if (request.mode == GetHeatmap::Request::MODE_VIEW_INDEX) {
    if (request.view_index < 0 || request.view_index >= views) {
      throw Error("Unknown view index " + std::to_string(request.view_index) +
                  ": the model has views 0 to " + std::to_string(views - 1) + ".");
    }
    view = request.view_index;
  } else if (request.mode == GetHeatmap::Request::MODE_DIRECTION) {
    view = scorer->nearestView(
        Eigen::Vector3d(request.direction.x, request.direction.y, request.direction.z));
  } else if (request.mode != GetHeatmap::Request::MODE_GLOBAL) {
    throw Error("Unknown mode " + std::to_string(int(request.mode)) +
                ": use MODE_GLOBAL (0), MODE_VIEW_INDEX (1) or MODE_DIRECTION (2).");
  }
  if (!request.scaling.empty() && request.scaling != "median" && request.scaling != "max") {
    throw Error("Unknown scaling \"" + request.scaling + "\": use \"median\" or \"max\".");
  }
  const Eigen::VectorXf scores =
      view < 0 ? model.global_scores : Eigen::VectorXf(model.score_matrix.col(view));
  response.view_index = view;
  response.min = minimumOfValid(scores);
  response.median = medianOfValid(scores);
  response.max = maximumOfValid(scores);
  const double black_at = request.scaling == "max" ? response.max : response.median;
  response.cloud = colouredSurface(model, scores, black_at, frame);
  response.scores.assign(scores.data(), scores.data() + scores.size());
  response.message =
      (view < 0 ? "Global scores." : "Scores of training view " + std::to_string(view) + ".") +
      whose;
}

void InformativenessServerRequests::nextBestView(const GetNextBestView::Request& request,
                                                 GetNextBestView::Response& response) {
  try {
    answerNextBestView(request, response);
    response.success = true;
  } catch (const std::exception& error) {
    response = GetNextBestView::Response();
    response.success = false;
    response.message = error.what();
  }
}

InformativenessServerRequests::Target InformativenessServerRequests::singleObjectTarget(
    const InformativenessServerRosParameters& settings) const {
  if (!scorer_) throw Error(kNoSingleModel);
  Target target;
  target.scorer = scorer_.get();
  // The object's pose (published by the estimator, or by a simulator's ground truth).
  try {
    target.world_from_object =
        lookupFixedFrom(settings.object_frame, settings.fixed_frame, "object pose");
  } catch (const Error&) {
    target.notes.push_back(
        "The object frame '" + settings.object_frame + "' is not available in tf; the object " +
        "was assumed at the origin of '" + settings.fixed_frame + "' with identity rotation.");
  }
  std::lock_guard<std::mutex> lock(belief_mutex_);
  if (latest_belief_) {
    target.belief = *latest_belief_;
    target.map = latest_map_;
    target.belief_note = "Belief from the latest estimate.";
  } else {
    target.belief_note = "No belief received yet: uniform belief.";
  }
  return target;
}

InformativenessServerRequests::Target InformativenessServerRequests::instanceTarget(
    const std::string& wanted) const {
  const ObjectInstanceMsg instance = chosenInstance(wanted);
  Target target;
  target.scorer = &libraryScorer(instance);
  // ~instances is in the fixed frame (receiveInstances checks it): no tf lookup needed, and the
  // pose is the one the belief belongs to.
  target.world_from_object = instancePose(instance);
  target.belief = fromBinghamMixtureMsg(instance.belief);
  target.map = mapEstimate(*target.belief);
  std::string note = "Instance " + instance.name + " (model " + instance.model;
  if (wanted == kMostUncertain) {
    char cone[32];
    std::snprintf(cone, sizeof(cone), "%.1f", instance.cone90_deg);
    note += ", the most uncertain: cone90 " + std::string(cone) + " deg";
  }
  target.notes.push_back(note + "), its pose from the latest instances.");
  target.belief_note = "Belief of " + instance.name + " from the latest instances.";
  return target;
}

void InformativenessServerRequests::answerNextBestView(const GetNextBestView::Request& request,
                                                       GetNextBestView::Response& response) {
  const InformativenessServerRosParameters settings = parameters();
  const ViewUtility utility =
      request.utility.empty() ? settings.default_utility : parseViewUtility(request.utility);
  Target target =
      request.instance.empty() ? singleObjectTarget(settings) : instanceTarget(request.instance);
  std::vector<std::string>& notes = target.notes;
  const Eigen::Isometry3d& world_from_object = target.world_from_object;

  // Candidate camera poses in the fixed frame.
  std::vector<Eigen::Isometry3d> candidates;
  if (!request.candidates.poses.empty()) {
    const Eigen::Isometry3d world_from_frame = lookupFixedFrom(
        request.candidates.header.frame_id, settings.fixed_frame, "candidate poses");
    for (std::size_t i = 0; i < request.candidates.poses.size(); ++i) {
      candidates.push_back(world_from_frame * fromPoseMsg(request.candidates.poses[i], i));
    }
  } else if (request.sample_count > 0) {
    candidates = sampleCandidatePoses(request.sample_count, request.sample_distance,
                                      world_from_object.translation());
  } else {
    throw Error(
        "There are no candidate poses and no sampling request (set candidates, or "
        "sample_count > 1 and sample_distance > 0).");
  }

  // The belief: the request's, else the target's (latest estimate or instance), else uniform.
  PlanningScene scene;
  scene.object_position = world_from_object.translation();
  scene.occluder_radius = settings.occluder_radius;
  if (request.use_belief) {
    if (!request.belief.header.frame_id.empty() &&
        request.belief.header.frame_id != settings.fixed_frame) {
      throw Error("The request's belief is in frame '" + request.belief.header.frame_id +
                  "', but beliefs must be in the fixed frame '" + settings.fixed_frame + "'.");
    }
    scene.belief = fromBinghamMixtureMsg(request.belief);
    scene.orientation = mapEstimate(scene.belief);
    notes.push_back("Belief from the request.");
  } else if (target.belief) {
    scene.belief = std::move(*target.belief);
    scene.orientation = target.map;
    notes.push_back(target.belief_note);
  } else {
    notes.push_back(target.belief_note);
    // No estimate yet: a uniform belief, and the object's orientation as tf has it.
    scene.orientation = quaternionFromRotationMatrix(world_from_object.linear());
  }

  if (request.use_occluder) {
    const pcl::PointCloud<pcl::PointXYZ> occluder = toXyzCloud(request.occluder);
    const Eigen::Isometry3d world_from_occluder =
        lookupFixedFrom(request.occluder.header.frame_id, settings.fixed_frame, "occluder points");
    for (const auto& p : occluder.points) {
      const Eigen::Vector3d point(p.x, p.y, p.z);
      if (point.allFinite()) scene.occluder_world.push_back(world_from_occluder * point);
    }
    if (scene.occluder_world.empty()) {
      throw Error("The occluder cloud has no finite points (set use_occluder to false for none).");
    }
  }

  std::vector<Eigen::Vector3d> positions;
  positions.reserve(candidates.size());
  for (const auto& pose : candidates) positions.push_back(pose.translation());
  NextBestViewOptions options;
  options.samples_per_component = settings.belief_samples_per_component;
  const std::vector<RankedCandidate> ranked =
      rankCandidates(*target.scorer, positions, utility, scene, options);

  response.ranked.header.frame_id = settings.fixed_frame;
  response.ranked.header.stamp = ros::Time::now();
  for (const RankedCandidate& candidate : ranked) {
    response.ranked.poses.push_back(toPoseMsg(candidates[candidate.index]));
    response.utilities.push_back(candidate.utility);
    response.candidate_indices.push_back(candidate.index);
  }
  response.best.header = response.ranked.header;
  response.best.pose = response.ranked.poses.front();
  response.best_index = ranked.front().index;
  std::string message = "Ranked " + std::to_string(ranked.size()) + " candidates by " +
                        viewUtilityName(utility) + ".";
  for (const auto& note : notes) message += " " + note;
  response.message = message;
}

}  // namespace vdc
