#pragma once

#include <diagnostic_updater/diagnostic_updater.h>
#include <geometry_msgs/TransformStamped.h>
#include <ros/ros.h>
#include <sensor_msgs/Image.h>
#include <sensor_msgs/PointCloud2.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_broadcaster.h>
#include <tf2_ros/transform_listener.h>
#include <view_direction_classification/ObjectInstances.h>
#include <view_direction_classification/QueryInstances.h>
#include <view_direction_classification/ResetInstance.h>

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "estimator_ros_parameters.h"
#include "heap_diagnostics.h"
#include "instance_messages.h"
#include "label_image_buffer.h"
#include "newest_cloud_worker.h"
#include "scene_ros_parameters.h"
#include "view_direction_classification/recognition/scene_estimator.h"
#include "view_direction_classification/scene/label_image.h"

namespace vdc {

// The orientation_estimator with a model library (~models; doc/nodes.md, "Several objects"):
// every known object of the scene. Each cloud (camera pose from tf2) goes to the core's
// SceneEstimator, which segments it, identifies the candidates against the library and keeps one
// estimator per instance; this class publishes ~instances, one tf frame per instance
// (fixed_frame -> "<model>_<n>", re-sent at ~tf_rate), ~markers with labels and
// ~memory_markers (every remembered instance, faded by age), serves ~reset, ~reset_instance and
// ~query_instances and reports diagnostics. As in OrientationEstimatorRos, the callback keeps only
// the newest cloud and one worker thread processes it; nothing a message contains ends the node.
// With segmentation `labels` the candidates are a detector's instance masks: each cloud takes the
// label image (`labels`) of its stamp, and a cloud without a usable one is skipped.
class SceneEstimatorRos {
 public:
  // Throws vdc::Error (or another std::exception) for invalid parameters or a library entry that
  // cannot be loaded (naming it): the caller reports it as a fatal start-up error.
  SceneEstimatorRos(ros::NodeHandle node, ros::NodeHandle private_node);
  ~SceneEstimatorRos();

  SceneEstimatorRos(const SceneEstimatorRos&) = delete;
  SceneEstimatorRos& operator=(const SceneEstimatorRos&) = delete;

 private:
  void cloudCallback(const sensor_msgs::PointCloud2ConstPtr& cloud);
  void labelsCallback(const sensor_msgs::ImageConstPtr& labels);
  void processCloud(const sensor_msgs::PointCloud2& cloud);
  // The label image of the cloud's stamp, checked against the cloud; false (skipped with the
  // reason) when there is none or it does not fit.
  bool labelsFor(const sensor_msgs::PointCloud2& cloud, LabelImage* labels);
  // Called with estimator_mutex_ held: the estimator's update, from the labels when given.
  SceneUpdate updateEstimator(const pcl::PointCloud<pcl::PointXYZ>& cloud, const LabelImage* labels,
                              const Eigen::Isometry3d& world_from_camera, double time);
  bool cameraPose(const sensor_msgs::PointCloud2& cloud, Eigen::Isometry3d* world_from_camera);
  void publishInstances(const std_msgs::Header& cloud_header);
  void publishPrimary(const view_direction_classification::ObjectInstances& all,
                      std::vector<geometry_msgs::TransformStamped>* transforms);
  void rebroadcastTransforms();
  void skip(const std::string& reason);
  bool resetService(std_srvs::Trigger::Request& request, std_srvs::Trigger::Response& response);
  bool resetInstanceService(view_direction_classification::ResetInstance::Request& request,
                            view_direction_classification::ResetInstance::Response& response);
  void forgetTransforms();
  // ~memory_file: loaded at start-up (a file that cannot be loaded is reported and kept, and
  // never saved over); saved at shutdown and on ~save_memory. saveMemory returns why it failed
  // (empty: saved); call it with estimator_mutex_ held.
  void loadMemory();
  std::string saveMemory();
  bool saveMemoryService(std_srvs::Trigger::Request& request,
                         std_srvs::Trigger::Response& response);
  // The object memory's question and its view (instance_query.h, memory_markers.h). These three
  // are called with estimator_mutex_ held: the fixed frame and the last cloud's stamp, the
  // instances as ~instances lists them, and ~memory_markers of them (while subscribed).
  std_msgs::Header memoryHeader() const;
  std::vector<view_direction_classification::ObjectInstance> memory() const;
  void publishMemoryMarkers(const std::vector<view_direction_classification::ObjectInstance>& all);
  // Takes estimator_mutex_: waits for a frame being processed.
  bool queryService(view_direction_classification::QueryInstances::Request& request,
                    view_direction_classification::QueryInstances::Response& response);
  // The timer's redraw, so ages advance while no frame is segmented; skipped while a frame is.
  void redrawMemory();
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status);

  ros::NodeHandle node_, private_node_;
  EstimatorRosParameters parameters_;
  SceneRosParameters scene_parameters_;
  InstanceMessageSettings message_settings_;
  // A library of one from ~model (segmentation `scene`): also ~estimate, ~pose, object_frame.
  bool single_object_topics_ = false;
  // segmentation `labels`: the candidates come from the label images.
  bool from_labels_ = false;
  LabelImageBuffer label_images_;

  std::mutex estimator_mutex_;  // guards estimator_ and last_stamp_
  std::unique_ptr<SceneEstimator> estimator_;
  ros::Time last_stamp_;

  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  tf2_ros::TransformBroadcaster tf_broadcaster_;
  // The instances' latest transforms, re-sent with the current time at ~tf_rate (/tf is not
  // latched). The worker writes them, the timer reads them.
  std::mutex transforms_mutex_;
  std::vector<geometry_msgs::TransformStamped> transforms_;
  ros::Timer transforms_timer_;
  ros::Publisher instances_publisher_, markers_publisher_, estimate_publisher_, pose_publisher_;
  // Why ~memory_file must not be saved over (it exists and could not be loaded); empty: it may.
  std::string memory_refused_;
  ros::Publisher memory_markers_publisher_;
  ros::Timer memory_timer_;
  ros::ServiceServer reset_server_, reset_instance_server_, save_memory_server_, query_server_;
  ros::Subscriber cloud_subscriber_, labels_subscriber_;
  diagnostic_updater::Updater diagnostics_;
  ros::Timer diagnostics_timer_;

  // Gives the heap's free pages back after the worker's clouds, at most every 10 s.
  PeriodicHeapRelease heap_release_{kNodeHeapReleasePeriodSeconds};
  // The newest unprocessed cloud's hand-over to the worker thread that processes it.
  std::unique_ptr<NewestCloudWorker> worker_;

  // Statistics for the diagnostics, guarded by statistics_mutex_.
  std::mutex statistics_mutex_;
  std::uint64_t received_ = 0, segmented_ = 0, still_ = 0, dropped_ = 0, skipped_ = 0;
  std::uint64_t labels_received_ = 0;
  int last_candidates_ = 0, last_unknown_ = 0, instances_ = 0, gone_instances_ = 0;
  std::string last_skip_reason_;
  std::string last_segmentation_note_;  // clusters dropped, no support found
  double last_segmentation_ms_ = 0, last_total_ms_ = 0;
  SceneStageTimes last_stage_ms_;  // of the last segmented frame
};

}  // namespace vdc
