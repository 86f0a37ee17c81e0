#include "scene_estimator_ros.h"

#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <tf2/exceptions.h>
#include <view_direction_classification/ObjectInstance.h>
#include <view_direction_classification/ObjectInstances.h>
#include <visualization_msgs/MarkerArray.h>

#include <boost/make_shared.hpp>

#include <chrono>
#include <exception>
#include <filesystem>
#include <sstream>
#include <utility>

#include "heap_diagnostics.h"
#include "instance_query.h"
#include "view_direction_classification/common/elapsed_time.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/recognition/scene_memory_file.h"
#include "view_direction_classification/ros/belief_markers.h"
#include "view_direction_classification/ros/bingham_conversions.h"
#include "view_direction_classification/ros/cloud_conversions.h"
#include "view_direction_classification/ros/geometry_conversions.h"
#include "view_direction_classification/ros/label_image_conversion.h"
#include "view_direction_classification/ros/memory_markers.h"
#include "view_direction_classification/scene/label_segmentation.h"

namespace vdc {
namespace {

using ObjectInstanceMsg = view_direction_classification::ObjectInstance;

// Label images kept for the clouds still to come: a second of a 30 Hz detector.
constexpr std::size_t kLabelImageCapacity = 30;
// ~memory_markers are redrawn this often [s] between frames, so that their ages advance.
constexpr double kMemoryRedrawPeriod = 1.0;

ModelLibrary loadLibrary(const SceneRosParameters& parameters) {
  return ModelLibrary::load(parameters.models);
}

SceneEstimatorParameters withInstanceSettings(SceneEstimatorParameters scene,
                                              const EstimatorParameters& instance) {
  scene.instance = instance;
  return scene;
}

// A text label above the instance: its name and identity probability.
visualization_msgs::Marker labelMarker(const std_msgs::Header& header,
                                       const ObjectInstance& instance,
                                       const Eigen::Vector3d& position, double height) {
  visualization_msgs::Marker label;
  label.header = header;
  label.ns = instance.name + "/label";
  label.type = visualization_msgs::Marker::TEXT_VIEW_FACING;
  label.pose.position.x = position.x();
  label.pose.position.y = position.y();
  label.pose.position.z = position.z() + height;
  label.pose.orientation.w = 1.0;
  label.scale.z = 0.03;
  label.color.r = label.color.g = label.color.b = label.color.a = 1.0f;
  std::ostringstream text;
  text.precision(2);
  text << instance.name << " (" << instance.identity_probability << ")";
  label.text = text.str();
  return label;
}

}  // namespace

SceneEstimatorRos::SceneEstimatorRos(ros::NodeHandle node, ros::NodeHandle private_node)
    : node_(node),
      private_node_(private_node),
      parameters_(readEstimatorRosParameters(private_node, private_node.hasParam("models"))),
      scene_parameters_(readSceneRosParameters(private_node, parameters_)),
      message_settings_{parameters_.position_variance, parameters_.converged_cone90_deg},
      single_object_topics_(!private_node.hasParam("models")),
      from_labels_(parameters_.core.segmentation.mode == SegmentationMode::kLabels),
      label_images_(kLabelImageCapacity),
      estimator_(std::make_unique<SceneEstimator>(
          loadLibrary(scene_parameters_),
          withInstanceSettings(scene_parameters_.scene, parameters_.core))),
      tf_listener_(tf_buffer_, node_),
      diagnostics_(node_, private_node_, private_node_.getNamespace()) {
  instances_publisher_ =
      private_node_.advertise<view_direction_classification::ObjectInstances>("instances", 1);
  markers_publisher_ = private_node_.advertise<visualization_msgs::MarkerArray>("markers", 1);
  memory_markers_publisher_ =
      private_node_.advertise<visualization_msgs::MarkerArray>("memory_markers", 1);
  memory_timer_ = private_node_.createTimer(ros::Duration(kMemoryRedrawPeriod),
                                            [this](const ros::TimerEvent&) { redrawMemory(); });
  if (single_object_topics_) {
    estimate_publisher_ = private_node_.advertise<BinghamMixtureMsg>("estimate", 1);
    pose_publisher_ = private_node_.advertise<geometry_msgs::PoseWithCovarianceStamped>("pose", 1);
  }
  reset_server_ = private_node_.advertiseService("reset", &SceneEstimatorRos::resetService, this);
  reset_instance_server_ = private_node_.advertiseService(
      "reset_instance", &SceneEstimatorRos::resetInstanceService, this);
  query_server_ =
      private_node_.advertiseService("query_instances", &SceneEstimatorRos::queryService, this);
  loadMemory();
  save_memory_server_ =
      private_node_.advertiseService("save_memory", &SceneEstimatorRos::saveMemoryService, this);
  diagnostics_.setHardwareID("none");
  diagnostics_.add("scene estimate", this, &SceneEstimatorRos::diagnose);
  diagnostics_timer_ = private_node_.createTimer(
      ros::Duration(1.0), [this](const ros::TimerEvent&) { diagnostics_.update(); });
  if (parameters_.publish_tf && parameters_.tf_rate > 0.0) {
    transforms_timer_ =
        private_node_.createTimer(ros::Duration(1.0 / parameters_.tf_rate),
                                  [this](const ros::TimerEvent&) { rebroadcastTransforms(); });
  }
  worker_ = std::make_unique<NewestCloudWorker>(
      [this](const sensor_msgs::PointCloud2& cloud) {
        processCloud(cloud);
        heap_release_.afterFrame(monotonicSeconds());
      },
      [this](const std::string& reason) { skip(reason); });
  // The label images first: a cloud's own image must not be missed because its subscription
  // came second.
  if (from_labels_) {
    labels_subscriber_ = node_.subscribe("labels", static_cast<std::uint32_t>(kLabelImageCapacity),
                                         &SceneEstimatorRos::labelsCallback, this);
  }
  cloud_subscriber_ = node_.subscribe("cloud", 1, &SceneEstimatorRos::cloudCallback, this);
  std::string names;
  for (const LibraryModel& model : estimator_->library().models()) {
    names += (names.empty() ? "" : ", ") + model.name;
  }
  ROS_INFO_NAMED(private_node_.getNamespace(),
                 "%s: a library of %d models (%s), fixed frame '%s', listening on %s",
                 private_node_.getNamespace().c_str(), estimator_->library().size(), names.c_str(),
                 parameters_.fixed_frame.c_str(), cloud_subscriber_.getTopic().c_str());
  if (from_labels_) {
    ROS_INFO_NAMED(private_node_.getNamespace(),
                   "%s: object candidates from the label images on %s",
                   private_node_.getNamespace().c_str(), labels_subscriber_.getTopic().c_str());
  }
}

SceneEstimatorRos::~SceneEstimatorRos() {
  transforms_timer_.stop();
  memory_timer_.stop();
  cloud_subscriber_.shutdown();
  labels_subscriber_.shutdown();
  worker_.reset();  // after the subscription: no cloud is offered to a stopped worker
  if (scene_parameters_.memory_file.empty()) return;
  std::lock_guard<std::mutex> lock(estimator_mutex_);
  const std::string failure = saveMemory();
  if (failure.empty()) {
    ROS_INFO("%s: the object memory is saved to %s", private_node_.getNamespace().c_str(),
             scene_parameters_.memory_file.c_str());
  } else {
    ROS_ERROR("%s: %s", private_node_.getNamespace().c_str(), failure.c_str());
  }
}

void SceneEstimatorRos::cloudCallback(const sensor_msgs::PointCloud2ConstPtr& cloud) {
  const bool replaced = worker_->offer(cloud);
  std::lock_guard<std::mutex> lock(statistics_mutex_);
  ++received_;
  if (replaced) ++dropped_;
}

void SceneEstimatorRos::labelsCallback(const sensor_msgs::ImageConstPtr& labels) {
  label_images_.add(labels);
  std::lock_guard<std::mutex> lock(statistics_mutex_);
  ++labels_received_;
}

bool SceneEstimatorRos::labelsFor(const sensor_msgs::PointCloud2& cloud, LabelImage* labels) {
  if (cloud.height <= 1) {
    skip("the cloud is not organised (" + std::to_string(cloud.width) + " x " +
         std::to_string(cloud.height) + "): a label image needs an organised cloud");
    return false;
  }
  const sensor_msgs::ImageConstPtr image =
      label_images_.find(cloud.header.stamp, scene_parameters_.labels_stamp_tolerance,
                         scene_parameters_.labels_timeout);
  if (!image) {
    std::ostringstream reason;
    reason << "no label image within labels_stamp_tolerance = "
           << scene_parameters_.labels_stamp_tolerance << " s of the cloud's stamp "
           << cloud.header.stamp << " (waited labels_timeout = " << scene_parameters_.labels_timeout
           << " s; " << label_images_.size() << " label image(s) buffered)";
    skip(reason.str());
    return false;
  }
  try {
    *labels = toLabelImage(*image);
  } catch (const Error& error) {
    skip(error.what());
    return false;
  }
  if (std::uint32_t(labels->width) != cloud.width ||
      std::uint32_t(labels->height) != cloud.height) {
    skip("the label image is " + std::to_string(labels->width) + " x " +
         std::to_string(labels->height) + ", the cloud " + std::to_string(cloud.width) + " x " +
         std::to_string(cloud.height) + ": they must be pixel-aligned");
    return false;
  }
  return true;
}

SceneUpdate SceneEstimatorRos::updateEstimator(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                               const LabelImage* labels,
                                               const Eigen::Isometry3d& world_from_camera,
                                               double time) {
  if (labels == nullptr) return estimator_->update(cloud, world_from_camera, time);
  // A still camera's frame is not segmented (the estimator would not use the segments).
  const auto start = std::chrono::steady_clock::now();
  SceneSegments segments;
  if (estimator_->willSegment(world_from_camera)) {
    segments = segmentLabels(cloud, *labels, scene_parameters_.scene.segmentation);
  }
  const double segmentation_ms = millisecondsSince(start);
  SceneUpdate update = estimator_->update(cloud, segments, world_from_camera, time);
  update.segmentation_ms = segmentation_ms;
  update.total_ms += segmentation_ms;
  return update;
}

bool SceneEstimatorRos::cameraPose(const sensor_msgs::PointCloud2& cloud,
                                   Eigen::Isometry3d* world_from_camera) {
  try {
    *world_from_camera = toIsometry(
        tf_buffer_.lookupTransform(parameters_.fixed_frame, cloud.header.frame_id,
                                   cloud.header.stamp, ros::Duration(parameters_.tf_timeout)));
    return true;
  } catch (const tf2::TransformException& error) {
    std::ostringstream reason;
    reason << "no transform from the cloud's frame '" << cloud.header.frame_id
           << "' to the fixed frame '" << parameters_.fixed_frame << "' at " << cloud.header.stamp
           << " within " << parameters_.tf_timeout << " s (" << error.what() << ")";
    skip(reason.str());
  } catch (const Error& error) {
    skip(error.what());
  }
  return false;
}

void SceneEstimatorRos::processCloud(const sensor_msgs::PointCloud2& cloud) {
  {
    std::lock_guard<std::mutex> lock(estimator_mutex_);
    if (!last_stamp_.isZero() && cloud.header.stamp < last_stamp_) {
      estimator_->reset();
      forgetTransforms();
      ROS_INFO_NAMED(private_node_.getNamespace(),
                     "%s: every instance forgotten: time went backwards (e.g. a looping bag)",
                     private_node_.getNamespace().c_str());
    }
    last_stamp_ = cloud.header.stamp;
  }
  const std::size_t points = std::size_t(cloud.width) * cloud.height;
  if (points > static_cast<std::size_t>(parameters_.max_points)) {
    skip("the cloud has " + std::to_string(points) +
         " points, more than ~max_points = " + std::to_string(parameters_.max_points));
    return;
  }
  Eigen::Isometry3d world_from_camera;
  if (!cameraPose(cloud, &world_from_camera)) return;
  pcl::PointCloud<pcl::PointXYZ> xyz;
  try {
    xyz = toXyzCloud(cloud);
  } catch (const Error& error) {
    skip(error.what());
    return;
  }
  LabelImage labels;
  if (from_labels_ && !labelsFor(cloud, &labels)) return;
  std::lock_guard<std::mutex> lock(estimator_mutex_);
  const SceneUpdate update = updateEstimator(xyz, from_labels_ ? &labels : nullptr,
                                             world_from_camera, cloud.header.stamp.toSec());
  std::lock_guard<std::mutex> statistics_lock(statistics_mutex_);
  last_skip_reason_.clear();
  if (!update.segmented) {
    ++still_;
    return;
  }
  ++segmented_;
  last_candidates_ = static_cast<int>(update.candidates.size());
  last_unknown_ = 0;
  for (const CandidateOutcome& candidate : update.candidates) {
    if (candidate.instance < 0) ++last_unknown_;
    if (candidate.moved) {
      ROS_INFO_NAMED(private_node_.getNamespace(), "%s: %s", private_node_.getNamespace().c_str(),
                     candidate.note.c_str());
    }
  }
  instances_ = gone_instances_ = 0;
  for (const ObjectInstance& instance : estimator_->instances()) {
    if (estimator_->confirmed(instance)) ++instances_;
    if (instance.presence.state == InstanceState::kGone) ++gone_instances_;
  }
  for (int id : update.gone) {
    const ObjectInstance* instance = estimator_->instance(id);
    if (instance == nullptr) continue;
    ROS_INFO_NAMED(private_node_.getNamespace(), "%s: %s is gone: its place was seen free",
                   private_node_.getNamespace().c_str(), instance->name.c_str());
  }
  last_segmentation_ms_ = update.segmentation_ms;
  last_total_ms_ = update.total_ms;
  if (update.segmented) last_stage_ms_ = update.stage_ms;
  last_segmentation_note_ = update.segmentation_note;
  publishInstances(cloud.header);
}

// Called with estimator_mutex_ held.
void SceneEstimatorRos::publishInstances(const std_msgs::Header& cloud_header) {
  std_msgs::Header header;
  header.stamp = cloud_header.stamp;
  header.frame_id = parameters_.fixed_frame;
  const auto message = boost::make_shared<view_direction_classification::ObjectInstances>();
  message->header = header;
  visualization_msgs::MarkerArray markers = makeClearMarkers(header);
  std::vector<geometry_msgs::TransformStamped> transforms;
  for (const ObjectInstance& instance : estimator_->instances()) {
    // An instance the views no longer support well enough is not published (nor its tf frame)
    // until they do again, or it is dropped. A gone one is listed with its last pose and its
    // state, but has no tf frame and no markers: nothing stands there.
    const std::optional<ObjectInstanceMsg> entry =
        toObjectInstanceMsg(*estimator_, instance, header, message_settings_);
    if (!entry) continue;
    message->instances.push_back(*entry);
    if (entry->state == ObjectInstanceMsg::GONE) continue;
    const std::optional<InstancePose> pose = reportedPose(*estimator_, instance);

    const visualization_msgs::MarkerArray axes = makeBeliefMarkers(
        header, instance.name, pose->position, pose->orientation, {}, parameters_.marker_length);
    markers.markers.insert(markers.markers.end(), axes.markers.begin(), axes.markers.end());
    markers.markers.push_back(
        labelMarker(header, instance, pose->position, parameters_.marker_length));
    geometry_msgs::TransformStamped transform;
    transform.header = header;
    transform.child_frame_id = instance.name;
    transform.transform.translation.x = pose->position.x();
    transform.transform.translation.y = pose->position.y();
    transform.transform.translation.z = pose->position.z();
    transform.transform.rotation = toQuaternionMsg(pose->orientation);
    transforms.push_back(transform);
  }
  instances_publisher_.publish(message);
  if (single_object_topics_) publishPrimary(*message, &transforms);
  if (markers_publisher_.getNumSubscribers() > 0) markers_publisher_.publish(markers);
  publishMemoryMarkers(message->instances);
  if (!parameters_.publish_tf) return;
  if (!transforms.empty()) tf_broadcaster_.sendTransform(transforms);
  std::lock_guard<std::mutex> lock(transforms_mutex_);
  transforms_ = std::move(transforms);
}

// A library of one keeps the single-object topics: ~estimate, ~pose and object_frame follow the
// instance seen in the most views (the lowest id among equals), so a user of one object sees
// what the one-object pipeline published.
void SceneEstimatorRos::publishPrimary(const view_direction_classification::ObjectInstances& all,
                                       std::vector<geometry_msgs::TransformStamped>* transforms) {
  const ObjectInstanceMsg* primary = nullptr;
  for (const ObjectInstanceMsg& instance : all.instances) {
    if (instance.state == ObjectInstanceMsg::GONE) continue;
    if (primary == nullptr || instance.views_fused > primary->views_fused) primary = &instance;
  }
  if (primary == nullptr) return;
  const auto estimate = boost::make_shared<BinghamMixtureMsg>(primary->belief);
  estimate->object_id = parameters_.object_id;
  estimate_publisher_.publish(estimate);
  const auto pose = boost::make_shared<geometry_msgs::PoseWithCovarianceStamped>();
  pose->header = all.header;
  pose->pose = primary->pose;
  pose_publisher_.publish(pose);
  geometry_msgs::TransformStamped transform;
  transform.header = all.header;
  transform.child_frame_id = parameters_.object_frame;
  transform.transform.translation.x = primary->pose.pose.position.x;
  transform.transform.translation.y = primary->pose.pose.position.y;
  transform.transform.translation.z = primary->pose.pose.position.z;
  transform.transform.rotation = primary->pose.pose.orientation;
  transforms->push_back(transform);
}

void SceneEstimatorRos::rebroadcastTransforms() {
  std::vector<geometry_msgs::TransformStamped> transforms;
  {
    std::lock_guard<std::mutex> lock(transforms_mutex_);
    transforms = transforms_;
  }
  if (transforms.empty()) return;
  // The objects are static in the fixed frame: the latest estimates hold now.
  const ros::Time now = ros::Time::now();
  for (auto& transform : transforms) transform.header.stamp = now;
  tf_broadcaster_.sendTransform(transforms);
}

void SceneEstimatorRos::forgetTransforms() {
  std::lock_guard<std::mutex> lock(transforms_mutex_);
  transforms_.clear();
}

std_msgs::Header SceneEstimatorRos::memoryHeader() const {
  std_msgs::Header header;
  header.stamp = last_stamp_;
  header.frame_id = parameters_.fixed_frame;
  return header;
}

std::vector<ObjectInstanceMsg> SceneEstimatorRos::memory() const {
  return reportedInstances(*estimator_, memoryHeader(), message_settings_);
}

bool SceneEstimatorRos::queryService(
    view_direction_classification::QueryInstances::Request& request,
    view_direction_classification::QueryInstances::Response& response) {
  std::vector<std::string> models;
  std::lock_guard<std::mutex> lock(estimator_mutex_);
  for (const LibraryModel& model : estimator_->library().models()) models.push_back(model.name);
  response.header = memoryHeader();
  // Answered from the memory now, not from the last ~instances: a reset since is seen.
  answerQuery(request, models, memory(), response);
  return true;
}

// Called with estimator_mutex_ held.
void SceneEstimatorRos::publishMemoryMarkers(const std::vector<ObjectInstanceMsg>& all) {
  if (memory_markers_publisher_.getNumSubscribers() == 0) return;
  memory_markers_publisher_.publish(makeMemoryMarkers(memoryHeader(), all, ros::Time::now(),
                                                      scene_parameters_.memory_fade_age,
                                                      0.5 * parameters_.marker_length));
}

void SceneEstimatorRos::redrawMemory() {
  if (memory_markers_publisher_.getNumSubscribers() == 0) return;
  // The worker holds the lock through a frame and publishes the markers when it is done: a
  // redraw now would only wait for it.
  std::unique_lock<std::mutex> lock(estimator_mutex_, std::try_to_lock);
  if (!lock.owns_lock()) return;
  publishMemoryMarkers(memory());
}

void SceneEstimatorRos::skip(const std::string& reason) {
  {
    std::lock_guard<std::mutex> lock(statistics_mutex_);
    ++skipped_;
    last_skip_reason_ = reason;
  }
  ROS_WARN_THROTTLE_NAMED(2.0, private_node_.getNamespace(), "%s: skipped a cloud: %s",
                          private_node_.getNamespace().c_str(), reason.c_str());
}

bool SceneEstimatorRos::resetService(std_srvs::Trigger::Request&,
                                     std_srvs::Trigger::Response& response) {
  std::lock_guard<std::mutex> lock(estimator_mutex_);
  estimator_->reset();
  forgetTransforms();
  response.success = true;
  response.message = "Every instance is forgotten.";
  return true;
}

void SceneEstimatorRos::loadMemory() {
  const std::string& path = scene_parameters_.memory_file;
  const std::string name = private_node_.getNamespace();
  std::error_code error;
  if (path.empty() || !std::filesystem::exists(path, error)) {
    if (!path.empty()) {
      ROS_INFO("%s: no object memory %s yet: starting empty", name.c_str(), path.c_str());
    }
    return;
  }
  std::lock_guard<std::mutex> lock(estimator_mutex_);
  try {
    loadSceneMemory(path, estimator_.get());
  } catch (const std::exception& e) {
    // Kept for the user to inspect: saving over it at shutdown would lose what it still holds.
    memory_refused_ = e.what();
    ROS_ERROR(
        "%s: the object memory could not be loaded, starting empty; it will not be saved "
        "over: %s",
        name.c_str(), e.what());
    return;
  }
  ROS_INFO("%s: %zu instances from the object memory %s", name.c_str(),
           estimator_->instances().size(), path.c_str());
  // Published once now, so the remembered instances' tf frames are re-sent at tf_rate before
  // the first cloud arrives (a planner may ask for one before the camera moves).
  std_msgs::Header now;
  now.stamp = ros::Time::now();
  publishInstances(now);
}

std::string SceneEstimatorRos::saveMemory() {
  const std::string& path = scene_parameters_.memory_file;
  if (path.empty()) return "no ~memory_file is set";
  if (!memory_refused_.empty()) {
    return "not saved over " + path + ", which could not be loaded at start-up: " + memory_refused_;
  }
  try {
    saveSceneMemory(*estimator_, path);
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

bool SceneEstimatorRos::saveMemoryService(std_srvs::Trigger::Request&,
                                          std_srvs::Trigger::Response& response) {
  std::lock_guard<std::mutex> lock(estimator_mutex_);
  const std::string failure = saveMemory();
  response.success = failure.empty();
  response.message = failure.empty() ? std::to_string(estimator_->instances().size()) +
                                           " instances saved to " + scene_parameters_.memory_file
                                     : failure;
  return true;
}

bool SceneEstimatorRos::resetInstanceService(
    view_direction_classification::ResetInstance::Request& request,
    view_direction_classification::ResetInstance::Response& response) {
  std::lock_guard<std::mutex> lock(estimator_mutex_);
  if (request.id == 0) {
    estimator_->reset();
    forgetTransforms();
    response.success = true;
    response.message = "Every instance is forgotten.";
    return true;
  }
  const ObjectInstance* instance = estimator_->instance(static_cast<int>(request.id));
  if (instance == nullptr) {
    response.success = false;
    response.message = "No instance has id " + std::to_string(request.id) + ".";
    return true;
  }
  const std::string name = instance->name;
  estimator_->resetInstance(static_cast<int>(request.id));
  {
    std::lock_guard<std::mutex> transforms_lock(transforms_mutex_);
    transforms_.erase(std::remove_if(transforms_.begin(), transforms_.end(),
                                     [&](const auto& t) { return t.child_frame_id == name; }),
                      transforms_.end());
  }
  response.success = true;
  response.message = name + " is forgotten.";
  return true;
}

void SceneEstimatorRos::diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) {
  std::lock_guard<std::mutex> lock(statistics_mutex_);
  if (!last_skip_reason_.empty()) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN,
                   "The last cloud was skipped: " + last_skip_reason_);
  } else if (segmented_ == 0) {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK, "Waiting for clouds.");
  } else {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK, "Following the scene's objects.");
  }
  status.add("clouds received", received_);
  if (from_labels_) status.add("label images received", labels_received_);
  status.add("clouds segmented", segmented_);
  status.add("clouds not segmented (the camera did not move)", still_);
  status.add("clouds dropped (a newer one arrived first)", dropped_);
  status.add("clouds skipped (bad input or no tf)", skipped_);
  status.add("instances (confirmed)", instances_);
  status.add("instances gone (their place seen free)", gone_instances_);
  status.add("last candidates", last_candidates_);
  status.add("last candidates unknown or not tried", last_unknown_);
  status.add("last skip reason", last_skip_reason_.empty() ? "none" : last_skip_reason_);
  status.add("last segmentation note",
             last_segmentation_note_.empty() ? "none" : last_segmentation_note_);
  status.add("last segmentation [ms]", last_segmentation_ms_);
  status.add("last frame [ms]", last_total_ms_);
  status.add("last segmented frame: preparation [ms]", last_stage_ms_.preparation);
  status.add("last segmented frame: instances' updates [ms]", last_stage_ms_.instances);
  status.add("last segmented frame: identification [ms]", last_stage_ms_.identification);
  status.add("last segmented frame: groups of pieces [ms]", last_stage_ms_.groups);
  status.add("last segmented frame: part search [ms]", last_stage_ms_.parts);
  addHeapUsage(status, heap_release_);
}

}  // namespace vdc
