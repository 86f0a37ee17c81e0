#include "orientation_estimator_ros.h"

#include <geometry_msgs/PoseWithCovarianceStamped.h>
#include <tf2/exceptions.h>
#include <view_direction_classification/BinghamMixture.h>
#include <visualization_msgs/MarkerArray.h>

#include <boost/make_shared.hpp>

#include <chrono>
#include <exception>
#include <random>
#include <sstream>
#include <utility>

#include "heap_diagnostics.h"
#include "view_direction_classification/common/elapsed_time.h"
#include "view_direction_classification/common/error.h"
#include "view_direction_classification/ros/belief_markers.h"
#include "view_direction_classification/ros/bingham_conversions.h"
#include "view_direction_classification/ros/cloud_conversions.h"
#include "view_direction_classification/ros/geometry_conversions.h"
#include "view_direction_classification/ros/reconfigurable_parameters.h"
#include "view_direction_classification/training/model_bundle.h"

namespace vdc {
namespace {

using Clock = std::chrono::steady_clock;

// The seed of the belief samples drawn as markers: the same belief always looks the same.
constexpr std::uint64_t kMarkerSeed = 1;

std::shared_ptr<const ModelBundle> loadModel(const std::string& path) {
  return std::make_shared<const ModelBundle>(loadModelBundle(path));
}

}  // namespace

OrientationEstimatorRos::OrientationEstimatorRos(ros::NodeHandle node, ros::NodeHandle private_node)
    : node_(node),
      private_node_(private_node),
      parameters_(readEstimatorRosParameters(private_node)),
      estimator_(std::make_unique<OrientationEstimator>(loadModel(parameters_.model_path),
                                                        parameters_.core)),
      tf_listener_(tf_buffer_, node_),
      diagnostics_(node_, private_node_, private_node_.getNamespace()) {
  estimate_publisher_ = private_node_.advertise<BinghamMixtureMsg>("estimate", 1);
  pose_publisher_ = private_node_.advertise<geometry_msgs::PoseWithCovarianceStamped>("pose", 1);
  markers_publisher_ = private_node_.advertise<visualization_msgs::MarkerArray>("markers", 1);
  reset_server_ =
      private_node_.advertiseService("reset", &OrientationEstimatorRos::resetService, this);

  diagnostics_.setHardwareID("none");
  diagnostics_.add("orientation estimate", this, &OrientationEstimatorRos::diagnose);
  diagnostics_timer_ = private_node_.createTimer(
      ros::Duration(1.0), [this](const ros::TimerEvent&) { diagnostics_.update(); });
  if (parameters_.publish_tf && parameters_.tf_rate > 0.0) {
    object_transform_timer_ =
        private_node_.createTimer(ros::Duration(1.0 / parameters_.tf_rate),
                                  [this](const ros::TimerEvent&) { rebroadcastObjectTransform(); });
  }

  startReconfigureServer();
  worker_ = std::make_unique<NewestCloudWorker>(
      [this](const sensor_msgs::PointCloud2& cloud) {
        processCloud(cloud);
        heap_release_.afterFrame(monotonicSeconds());
      },
      [this](const std::string& reason) { skip(reason); });
  // Queue of one: the worker only ever wants the newest cloud.
  cloud_subscriber_ = node_.subscribe("cloud", 1, &OrientationEstimatorRos::cloudCallback, this);
  ROS_INFO_NAMED(
      private_node_.getNamespace(),
      "%s: model %s (%d viewing directions, kappa %.1f), fixed frame '%s', listening on %s",
      private_node_.getNamespace().c_str(), parameters_.model_path.c_str(),
      static_cast<int>(estimator_->model().view_directions.size()), estimator_->kappa(),
      parameters_.fixed_frame.c_str(), cloud_subscriber_.getTopic().c_str());
}

OrientationEstimatorRos::~OrientationEstimatorRos() {
  reconfigure_server_.reset();
  object_transform_timer_.stop();
  cloud_subscriber_.shutdown();
  worker_.reset();  // after the subscription: no cloud is offered to a stopped worker
}

void OrientationEstimatorRos::cloudCallback(const sensor_msgs::PointCloud2ConstPtr& cloud) {
  const bool replaced = worker_->offer(cloud);
  std::lock_guard<std::mutex> lock(statistics_mutex_);
  ++received_;
  if (replaced) ++dropped_;
}

void OrientationEstimatorRos::processCloud(const sensor_msgs::PointCloud2& cloud) {
  const std::string& frame = cloud.header.frame_id;
  {
    std::lock_guard<std::mutex> lock(estimator_mutex_);
    if (!last_stamp_.isZero() && cloud.header.stamp < last_stamp_) {
      std::ostringstream why;
      why << "time went backwards (cloud stamp " << cloud.header.stamp << " < last " << last_stamp_
          << ", e.g. a looping bag)";
      resetBelief(why.str());
    }
    last_stamp_ = cloud.header.stamp;
  }
  const std::size_t points = std::size_t(cloud.width) * cloud.height;
  if (points > static_cast<std::size_t>(parameters_.max_points)) {
    skip("the cloud in frame '" + frame + "' has " + std::to_string(points) +
         " points, more than ~max_points = " + std::to_string(parameters_.max_points));
    return;
  }

  Clock::time_point start = Clock::now();
  geometry_msgs::TransformStamped world_from_camera_msg;
  try {
    world_from_camera_msg = tf_buffer_.lookupTransform(
        parameters_.fixed_frame, frame, cloud.header.stamp, ros::Duration(parameters_.tf_timeout));
  } catch (const tf2::TransformException& error) {
    std::ostringstream reason;
    reason << "no transform from the cloud's frame '" << frame << "' to the fixed frame '"
           << parameters_.fixed_frame << "' at " << cloud.header.stamp << " within "
           << parameters_.tf_timeout << " s (" << error.what() << ")";
    skip(reason.str());
    return;
  }
  const double tf_ms = millisecondsSince(start);

  start = Clock::now();
  Eigen::Isometry3d world_from_camera;
  pcl::PointCloud<pcl::PointXYZ> xyz;
  try {
    world_from_camera = toIsometry(world_from_camera_msg);
    xyz = toXyzCloud(cloud);
  } catch (const Error& error) {
    skip(error.what());
    return;
  }
  const double conversion_ms = millisecondsSince(start);

  std::lock_guard<std::mutex> lock(estimator_mutex_);
  const ViewUpdate update = estimator_->update(xyz, world_from_camera, cloud.header.stamp.toSec());
  if (!update.reset_reason.empty()) announceReset(update.reset_reason);
  if (!update.rebuild_reason.empty()) {
    ROS_INFO_THROTTLE_NAMED(2.0, private_node_.getNamespace(),
                            "%s: belief rebuilt from this view: %s",
                            private_node_.getNamespace().c_str(), update.rebuild_reason.c_str());
  }
  if (update.outcome == FrameOutcome::kSkipped) {
    skip("cloud in frame '" + frame + "' not fused: " + update.skip_reason);
    return;
  }
  if (update.outcome == FrameOutcome::kNotNovel) {
    std::lock_guard<std::mutex> statistics_lock(statistics_mutex_);
    ++not_novel_;
    last_skip_reason_.clear();
    last_tf_ms_ = tf_ms;
    last_conversion_ms_ = conversion_ms;
    last_selection_ms_ = update.timing.selection;
    return;
  }
  start = Clock::now();
  publishEstimate(cloud.header);
  const double publish_ms = millisecondsSince(start);

  std::lock_guard<std::mutex> statistics_lock(statistics_mutex_);
  ++processed_;
  views_fused_ = estimator_->viewsFused();
  last_skip_reason_.clear();
  last_tf_ms_ = tf_ms;
  last_conversion_ms_ = conversion_ms;
  last_selection_ms_ = update.timing.selection;
  last_timing_ = update.timing;
  last_publish_ms_ = publish_ms;
}

// Called with estimator_mutex_ held.
void OrientationEstimatorRos::publishEstimate(const std_msgs::Header& cloud_header) {
  std_msgs::Header header;
  header.stamp = cloud_header.stamp;
  header.frame_id = parameters_.fixed_frame;
  const Eigen::Vector4d map = estimator_->mapOrientation();

  // Published as shared pointers, never touched after: a server nodelet in the same manager
  // gets this object without a copy.
  const auto estimate =
      boost::make_shared<BinghamMixtureMsg>(toBinghamMixtureMsg(estimator_->belief()));
  estimate->header = header;
  estimate->object_id = parameters_.object_id;
  estimate->map_orientation = toQuaternionMsg(map);
  estimate->entropy = estimator_->entropy();
  // The cone and ~pose's covariance come from the same belief samples (BeliefSpread).
  estimate->views_fused = static_cast<std::uint32_t>(estimator_->viewsFused());
  estimate->cone90_deg = estimator_->spread().cone90 * 180.0 / M_PI;
  estimate->converged = estimate->cone90_deg <= parameters_.converged_cone90_deg;
  estimate_publisher_.publish(estimate);

  const std::optional<Eigen::Vector3d> position = estimator_->positionEstimate();
  if (!position) return;  // cannot happen after a fused view; nothing to place the pose at
  const auto pose = boost::make_shared<geometry_msgs::PoseWithCovarianceStamped>();
  pose->header = header;
  // The refinement's fit gives the position's covariance; without it, the configured variance.
  const Eigen::Matrix3d position_covariance = estimator_->positionCovariance().value_or(
      parameters_.position_variance * Eigen::Matrix3d::Identity());
  pose->pose = toPoseWithCovarianceMsg(*position, map, position_covariance,
                                       estimator_->orientationCovariance());
  pose_publisher_.publish(pose);

  // Sampling costs time; rviz may not be listening (image_proc's habit: work only for listeners).
  if (markers_publisher_.getNumSubscribers() > 0) {
    std::mt19937_64 generator(kMarkerSeed);
    const std::vector<Eigen::Vector4d> samples =
        estimator_->belief().sample(parameters_.marker_samples, generator);
    markers_publisher_.publish(makeBeliefMarkers(header, "orientation_estimate", *position, map,
                                                 samples, parameters_.marker_length));
  }

  if (parameters_.publish_tf) {
    geometry_msgs::TransformStamped transform;
    transform.header = header;
    transform.child_frame_id = parameters_.object_frame;
    transform.transform.translation.x = position->x();
    transform.transform.translation.y = position->y();
    transform.transform.translation.z = position->z();
    transform.transform.rotation = toQuaternionMsg(map);
    tf_broadcaster_.sendTransform(transform);
    std::lock_guard<std::mutex> transform_lock(object_transform_mutex_);
    object_transform_ = transform;
  }
}

void OrientationEstimatorRos::rebroadcastObjectTransform() {
  std::optional<geometry_msgs::TransformStamped> transform;
  {
    std::lock_guard<std::mutex> lock(object_transform_mutex_);
    transform = object_transform_;
  }
  if (!transform) return;
  // The object is static in the fixed frame: the latest estimate holds now.
  transform->header.stamp = ros::Time::now();
  tf_broadcaster_.sendTransform(*transform);
}

void OrientationEstimatorRos::skip(const std::string& reason) {
  {
    std::lock_guard<std::mutex> lock(statistics_mutex_);
    ++skipped_;
    last_skip_reason_ = reason;
  }
  ROS_WARN_THROTTLE_NAMED(2.0, private_node_.getNamespace(), "%s: skipped a cloud: %s",
                          private_node_.getNamespace().c_str(), reason.c_str());
}

bool OrientationEstimatorRos::resetService(std_srvs::Trigger::Request&,
                                           std_srvs::Trigger::Response& response) {
  std::lock_guard<std::mutex> lock(estimator_mutex_);
  resetBelief("~reset was called");
  response.success = true;
  response.message = "The orientation belief is uniform again.";
  return true;
}

// Called with estimator_mutex_ held.
void OrientationEstimatorRos::resetBelief(const std::string& why) {
  estimator_->reset();
  announceReset(why);
}

// Called with estimator_mutex_ held, after the core's belief went back to uniform.
void OrientationEstimatorRos::announceReset(const std::string& why) {
  {
    std::lock_guard<std::mutex> lock(statistics_mutex_);
    views_fused_ = estimator_->viewsFused();
  }
  {
    // No object pose until the next estimate: listeners see the frame go stale, not a pose the
    // uniform belief no longer supports.
    std::lock_guard<std::mutex> lock(object_transform_mutex_);
    object_transform_.reset();
  }
  ROS_INFO_NAMED(private_node_.getNamespace(), "%s: belief reset: %s",
                 private_node_.getNamespace().c_str(), why.c_str());
  std_msgs::Header header;
  header.stamp = ros::Time::now();
  header.frame_id = parameters_.fixed_frame;
  markers_publisher_.publish(makeClearMarkers(header));
}

void OrientationEstimatorRos::startReconfigureServer() {
  reconfigure_server_ = std::make_unique<dynamic_reconfigure::Server<OrientationEstimatorConfig>>(
      reconfigure_mutex_, private_node_);
  // The start-up parameters are authoritative: the server shows (and its first callback
  // applies) what the node runs with, not the .cfg's defaults for parameters the yaml left unset.
  reconfigure_server_->updateConfig(
      toReconfigureConfig<OrientationEstimatorConfig>(estimatorParameterTable(), parameters_));
  reconfigure_server_->setCallback([this](OrientationEstimatorConfig& config, std::uint32_t level) {
    reconfigure(config, level);
  });
}

// Runs in the reconfigure service's callback. Applied under estimator_mutex_, so a change never
// lands inside an update: it takes effect from the next cloud the worker processes.
void OrientationEstimatorRos::reconfigure(OrientationEstimatorConfig& config, std::uint32_t) {
  std::lock_guard<std::mutex> lock(estimator_mutex_);
  try {
    const EstimatorRosParameters next =
        withReconfigureConfig(estimatorParameterTable(), parameters_, config);
    estimator_->setParameters(next.core);  // checks again; throws before changing anything
    parameters_.core = next.core;
    parameters_.converged_cone90_deg = next.converged_cone90_deg;
  } catch (const std::exception& error) {
    ROS_WARN_NAMED(private_node_.getNamespace(),
                   "%s: reconfigure refused, the previous settings stay: %s",
                   private_node_.getNamespace().c_str(), error.what());
    // The server stores and publishes (~parameter_updates, the service's answer) what the
    // callback leaves in `config`: the settings the node still runs with.
    config =
        toReconfigureConfig<OrientationEstimatorConfig>(estimatorParameterTable(), parameters_);
    return;
  }
  ROS_INFO_NAMED(private_node_.getNamespace(),
                 "%s: reconfigured (from the next cloud): n_feat %d, kappa %g, max_components %d, "
                 "min_weight %g, psum_exponent %g, min_view_separation %g, "
                 "independent_view_separation %g, min_information_gain %g, "
                 "converged_cone90_deg %g, refinement %s",
                 private_node_.getNamespace().c_str(), config.n_feat, config.kappa,
                 config.max_components, config.min_weight, config.psum_exponent,
                 config.min_view_separation, config.independent_view_separation,
                 config.min_information_gain, config.converged_cone90_deg,
                 config.refinement.c_str());
}

void OrientationEstimatorRos::diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) {
  std::lock_guard<std::mutex> lock(statistics_mutex_);
  if (!last_skip_reason_.empty()) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN,
                   "The last cloud was skipped: " + last_skip_reason_);
  } else if (processed_ == 0) {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK, "Waiting for clouds.");
  } else {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK, "Fusing new views.");
  }
  status.add("clouds received", received_);
  status.add("clouds fused (new views)", processed_);
  status.add("clouds not novel (a view already fused)", not_novel_);
  status.add("clouds dropped (a newer one arrived first)", dropped_);
  status.add("clouds skipped (bad input or no tf)", skipped_);
  status.add("views fused in the belief", views_fused_);
  status.add("last skip reason", last_skip_reason_.empty() ? "none" : last_skip_reason_);
  status.add("last tf lookup [ms]", last_tf_ms_);
  status.add("last conversion [ms]", last_conversion_ms_);
  status.add("last frame selection [ms]", last_selection_ms_);
  status.add("last segmentation [ms]", last_timing_.segmentation);
  status.add("last features [ms]", last_timing_.features);
  status.add("last classification [ms]", last_timing_.classification);
  status.add("last measurement [ms]", last_timing_.measurement);
  status.add("last fusion [ms]", last_timing_.fusion);
  status.add("last publishing [ms]", last_publish_ms_);
  addHeapUsage(status, heap_release_);
}

}  // namespace vdc
