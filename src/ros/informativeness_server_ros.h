#pragma once

#include <dynamic_reconfigure/server.h>
#include <ros/ros.h>
#include <sensor_msgs/PointCloud2.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>
#include <view_direction_classification/BinghamMixture.h>
#include <view_direction_classification/GetHeatmap.h>
#include <view_direction_classification/GetNextBestView.h>
#include <view_direction_classification/ObjectInstances.h>
#include <visualization_msgs/MarkerArray.h>

#include <Eigen/Geometry>

#include <cstdint>
#include <memory>
#include <string>

#include "informativeness_server_requests.h"
#include "informativeness_server_ros_parameters.h"
#include "view_direction_classification/InformativenessServerConfig.h"

namespace vdc {

// Generated from cfg/InformativenessServer.cfg.
using InformativenessServerConfig = view_direction_classification::InformativenessServerConfig;

// The informativeness server node (doc/nodes.md): serves a model bundle's view and
// surface informativeness. Latched `~heatmap` (the surface set coloured by the global score) and
// `~view_scores` (the training directions coloured by their view score), re-sent every
// republish_period; services `~get_heatmap` and `~next_best_view`; tracks the belief published on
// `estimate` and, with a model library (~models), the instances published on `instances`, so a
// request can name the instance to plan for. Parameters are documented in
// config/informativeness_server.yaml; the utility settings of cfg/InformativenessServer.cfg can be
// changed while it runs (dynamic_reconfigure). Every bad request is answered with success = false
// and a message; the server keeps serving.
class InformativenessServerRos {
 public:
  // Throws vdc::Error for a missing or invalid model bundle or invalid parameters.
  InformativenessServerRos(ros::NodeHandle node, ros::NodeHandle private_node);

 private:
  bool getHeatmap(view_direction_classification::GetHeatmap::Request& request,
                  view_direction_classification::GetHeatmap::Response& response);
  bool nextBestView(view_direction_classification::GetNextBestView::Request& request,
                    view_direction_classification::GetNextBestView::Response& response);
  void receiveEstimate(const view_direction_classification::BinghamMixture::ConstPtr& msg);
  void receiveInstances(const view_direction_classification::ObjectInstances::ConstPtr& msg);
  void logStart() const;
  void startReconfigureServer();
  void reconfigure(InformativenessServerConfig& config, std::uint32_t level);

  // fixed_frame <- frame through tf. Throws vdc::Error naming the frame if tf has no such
  // transform within tf_timeout.
  Eigen::Isometry3d lookupFixedFrom(const std::string& frame, const char* what) const;
  // Builds the heatmap and view-score messages from the model (kept for the republish timer)
  // and publishes them once, latched.
  void publishScoreTopics();

  ros::NodeHandle node_, private_node_;
  InformativenessServerRosParameters parameters_;
  tf2_ros::Buffer tf_buffer_;
  tf2_ros::TransformListener tf_listener_;
  // What the services answer and the belief they use (the node's logic without transport).
  // The requests' belief lock keeps the estimate callback and the services apart; they run one
  // at a time anyway (ros::spin() in the node; the nodelet's single-threaded queue on a manager
  // worker thread), the lock keeps that true on a multi-threaded spinner.
  std::unique_ptr<InformativenessServerRequests> requests_;
  ros::Publisher heatmap_publisher_, view_scores_publisher_;
  // What ~heatmap and ~view_scores carry (fixed after start-up), re-sent every republish_period.
  sensor_msgs::PointCloud2 heatmap_msg_;
  visualization_msgs::MarkerArray view_scores_msg_;
  ros::WallTimer republish_timer_;
  ros::ServiceServer heatmap_service_, next_best_view_service_;
  ros::Subscriber estimate_subscriber_;
  ros::Subscriber instances_subscriber_;  // with ~models only
  // dynamic_reconfigure's server (~set_parameters, ~parameter_updates). Its callback runs on the
  // same queue as the services (the requests' own lock guards their settings anyway).
  boost::recursive_mutex reconfigure_mutex_;
  std::unique_ptr<dynamic_reconfigure::Server<InformativenessServerConfig>> reconfigure_server_;
};

}  // namespace vdc
