#pragma once

#include <diagnostic_updater/diagnostic_updater.h>
#include <dynamic_reconfigure/server.h>
#include <geometry_msgs/TransformStamped.h>
#include <ros/ros.h>
#include <sensor_msgs/PointCloud2.h>
#include <std_srvs/Trigger.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_broadcaster.h>
#include <tf2_ros/transform_listener.h>

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "estimator_ros_parameters.h"
#include "heap_diagnostics.h"
#include "newest_cloud_worker.h"
#include "view_direction_classification/OrientationEstimatorConfig.h"
#include "view_direction_classification/estimation/orientation_estimator.h"

namespace vdc {

// Generated from cfg/OrientationEstimator.cfg.
using OrientationEstimatorConfig = view_direction_classification::OrientationEstimatorConfig;

// The orientation_estimator's ROS side (doc/nodes.md): reads the parameters, loads
// the model, subscribes `cloud`, looks up the camera pose with tf2, calls the core
// OrientationEstimator and publishes ~estimate, ~pose, ~markers and the object's tf (re-sent at
// ~tf_rate); serves ~reset and reports diagnostics. The same class runs in the node binary and in
// the nodelet.
//
// The stream's frames are selected by the core: only a new view of the object is featurised and
// fused; the others cost a tf lookup and one pass over the cloud (counted as not novel).
// A camera can be faster than the estimator: the subscriber callback only keeps the newest
// cloud, and one worker thread processes whatever is newest when it is free (the clouds it never
// saw are counted as skipped). Bad clouds are logged (throttled) and skipped; nothing a message
// contains ends the node.
//
// Threads: the cloud callback, the two timers and ~reset are callbacks of one node handle's
// queue and run one at a time, on ros::spin()'s thread in the node and on one of the manager's
// worker threads in the nodelet (its getNodeHandle() queue is single-threaded); the worker
// thread runs beside them, and the mutexes guard what it shares with them. tf2's listener
// fills the buffer from a thread of its own. Log lines go to the logger named after the node or
// nodelet (ROS_*_NAMED with the private namespace, which is what NODELET_* uses). The settings
// of cfg/OrientationEstimator.cfg can be changed while it runs (dynamic_reconfigure, its service
// callback runs on the same queue): a change lands between two clouds.
class OrientationEstimatorRos {
 public:
  // Throws vdc::Error (or another std::exception) for invalid parameters or an unreadable model:
  // the caller reports it as a fatal start-up error.
  OrientationEstimatorRos(ros::NodeHandle node, ros::NodeHandle private_node);
  ~OrientationEstimatorRos();

  OrientationEstimatorRos(const OrientationEstimatorRos&) = delete;
  OrientationEstimatorRos& operator=(const OrientationEstimatorRos&) = delete;

 private:
  void cloudCallback(const sensor_msgs::PointCloud2ConstPtr& cloud);
  void processCloud(const sensor_msgs::PointCloud2& cloud);
  void publishEstimate(const std_msgs::Header& cloud_header);
  void rebroadcastObjectTransform();
  void skip(const std::string& reason);
  bool resetService(std_srvs::Trigger::Request& request, std_srvs::Trigger::Response& response);
  void resetBelief(const std::string& why);
  void announceReset(const std::string& why);
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status);
  void startReconfigureServer();
  void reconfigure(OrientationEstimatorConfig& config, std::uint32_t level);

  ros::NodeHandle node_, private_node_;
  EstimatorRosParameters parameters_;

  // The core estimator, guarded by estimator_mutex_ (the worker updates it, ~reset resets it, a
  // reconfigure sets its parameters and parameters_.core and .converged_cone90_deg; the other
  // fields of parameters_ never change after start-up).
  std::mutex estimator_mutex_;
  std::unique_ptr<OrientationEstimator> estimator_;
  ros::Time last_stamp_;

  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  tf2_ros::TransformBroadcaster tf_broadcaster_;
  // The latest estimate's fixed_frame -> object_frame transform, re-sent with the current time
  // at ~tf_rate (as robot_state_publisher does for fixed joints): /tf is not latched, so rviz or
  // a listener started after the last estimate would otherwise never learn the object frame.
  // Empty before the first estimate and after ~reset. The worker writes it, the timer reads it.
  std::mutex object_transform_mutex_;
  std::optional<geometry_msgs::TransformStamped> object_transform_;
  ros::Timer object_transform_timer_;
  ros::Publisher estimate_publisher_, pose_publisher_, markers_publisher_;
  ros::ServiceServer reset_server_;
  ros::Subscriber cloud_subscriber_;
  diagnostic_updater::Updater diagnostics_;
  ros::Timer diagnostics_timer_;
  // dynamic_reconfigure's server (~set_parameters, ~parameter_updates); its mutex serialises
  // its callback with updateConfig.
  boost::recursive_mutex reconfigure_mutex_;
  std::unique_ptr<dynamic_reconfigure::Server<OrientationEstimatorConfig>> reconfigure_server_;

  // Gives the heap's free pages back after the worker's clouds, at most every 10 s.
  PeriodicHeapRelease heap_release_{kNodeHeapReleasePeriodSeconds};
  // The newest unprocessed cloud's hand-over to the worker thread that processes it.
  std::unique_ptr<NewestCloudWorker> worker_;

  // Statistics for the diagnostics, guarded by statistics_mutex_.
  std::mutex statistics_mutex_;
  std::uint64_t received_ = 0, processed_ = 0, not_novel_ = 0, dropped_ = 0, skipped_ = 0;
  int views_fused_ = 0;
  std::string last_skip_reason_;
  double last_tf_ms_ = 0, last_conversion_ms_ = 0, last_selection_ms_ = 0, last_publish_ms_ = 0;
  UpdateTiming last_timing_;
};

}  // namespace vdc
