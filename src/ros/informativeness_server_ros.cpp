#include "informativeness_server_ros.h"

#include <sensor_msgs/PointCloud2.h>
#include <tf2_eigen/tf2_eigen.h>
#include <visualization_msgs/MarkerArray.h>

#include <cstdio>
#include <string>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/recognition/model_library.h"
#include "view_direction_classification/ros/geometry_conversions.h"
#include "view_direction_classification/ros/reconfigurable_parameters.h"
#include "view_direction_classification/visualisation/heatmap_colours.h"

namespace vdc {
namespace {

using view_direction_classification::GetHeatmap;
using view_direction_classification::GetNextBestView;

std_msgs::ColorRGBA toColour(const std::array<std::uint8_t, 3>& rgb) {
  std_msgs::ColorRGBA colour;
  colour.r = rgb[0] / 255.0f;
  colour.g = rgb[1] / 255.0f;
  colour.b = rgb[2] / 255.0f;
  colour.a = 1.0f;
  return colour;
}

// ~model's bundle, or null without one (a server for a library's instances only).
std::shared_ptr<const ModelBundle> loadSingleModel(
    const InformativenessServerRosParameters& parameters) {
  if (parameters.model_path.empty()) return nullptr;
  return std::make_shared<const ModelBundle>(loadModelBundle(parameters.model_path));
}

// ~models' bundles, loaded and checked as the estimator loads its library (the same map).
ServedLibrary loadLibrary(const InformativenessServerRosParameters& parameters) {
  ServedLibrary library;
  if (parameters.models.empty()) return library;
  const ModelLibrary loaded = ModelLibrary::load(parameters.models);
  for (const LibraryModel& model : loaded.models()) {
    library.emplace_back(model.name, model.bundle);
  }
  return library;
}

}  // namespace

InformativenessServerRos::InformativenessServerRos(ros::NodeHandle node,
                                                   ros::NodeHandle private_node)
    : node_(node),
      private_node_(private_node),
      parameters_(readInformativenessServerRosParameters(private_node)),
      tf_listener_(tf_buffer_) {
  requests_ = std::make_unique<InformativenessServerRequests>(
      loadSingleModel(parameters_), parameters_,
      [this](const std::string& frame, const char* what) { return lookupFixedFrom(frame, what); },
      loadLibrary(parameters_));

  heatmap_publisher_ = private_node_.advertise<sensor_msgs::PointCloud2>("heatmap", 1, true);
  view_scores_publisher_ =
      private_node_.advertise<visualization_msgs::MarkerArray>("view_scores", 1, true);
  // The topics draw the one model in object_frame; a server for instances only has none.
  if (requests_->hasSingleModel()) publishScoreTopics();
  if (requests_->hasSingleModel() && parameters_.republish_period > 0.0) {
    // Latching alone is not enough for rviz: tf2 drops a stamp-0 message that arrives before its
    // frame exists, for good, as soon as the frame appears (BufferCore::testTransformableRequests
    // judges time 0 older than the cache). The object frame only exists after the first
    // estimate, so a viewer gets the heatmap within one period of learning the frame.
    republish_timer_ = private_node_.createWallTimer(
        ros::WallDuration(parameters_.republish_period), [this](const ros::WallTimerEvent&) {
          heatmap_publisher_.publish(heatmap_msg_);
          view_scores_publisher_.publish(view_scores_msg_);
        });
  }
  heatmap_service_ =
      private_node_.advertiseService("get_heatmap", &InformativenessServerRos::getHeatmap, this);
  next_best_view_service_ = private_node_.advertiseService(
      "next_best_view", &InformativenessServerRos::nextBestView, this);
  estimate_subscriber_ =
      node_.subscribe("estimate", 1, &InformativenessServerRos::receiveEstimate, this);
  // Only a library can plan for the instances (without one, naming an instance is refused).
  if (!parameters_.models.empty()) {
    instances_subscriber_ =
        node_.subscribe("instances", 1, &InformativenessServerRos::receiveInstances, this);
  }
  startReconfigureServer();
  logStart();
}

void InformativenessServerRos::logStart() const {
  if (requests_->hasSingleModel()) {
    ROS_INFO_NAMED(
        private_node_.getNamespace(),
        "Informativeness server: model %s (%d views, %zu surface points), object frame %s in %s",
        parameters_.model_path.c_str(), requests_->scorer().viewCount(),
        requests_->model().surface_points.size(), parameters_.object_frame.c_str(),
        parameters_.fixed_frame.c_str());
  }
  if (parameters_.models.empty()) return;
  std::string names;
  for (const auto& entry : parameters_.models) names += (names.empty() ? "" : ", ") + entry.first;
  ROS_INFO_NAMED(private_node_.getNamespace(),
                 "Informativeness server: library of %zu models (%s) for the instances on %s",
                 parameters_.models.size(), names.c_str(),
                 instances_subscriber_.getTopic().c_str());
}

void InformativenessServerRos::startReconfigureServer() {
  reconfigure_server_ = std::make_unique<dynamic_reconfigure::Server<InformativenessServerConfig>>(
      reconfigure_mutex_, private_node_);
  // The start-up parameters are authoritative: the server shows (and its first callback
  // applies) what the node runs with, not the .cfg's defaults.
  reconfigure_server_->updateConfig(toReconfigureConfig<InformativenessServerConfig>(
      informativenessServerParameterTable(), parameters_));
  reconfigure_server_->setCallback([this](InformativenessServerConfig& config,
                                          std::uint32_t level) { reconfigure(config, level); });
}

// Runs in the reconfigure service's callback; the next request uses the new settings.
void InformativenessServerRos::reconfigure(InformativenessServerConfig& config, std::uint32_t) {
  try {
    parameters_ = withReconfigureConfig(informativenessServerParameterTable(), parameters_, config);
  } catch (const std::exception& error) {
    ROS_WARN_NAMED(private_node_.getNamespace(),
                   "%s: reconfigure refused, the previous settings stay: %s",
                   private_node_.getNamespace().c_str(), error.what());
    // The server stores and publishes what the callback leaves in `config`.
    config = toReconfigureConfig<InformativenessServerConfig>(informativenessServerParameterTable(),
                                                              parameters_);
    return;
  }
  requests_->setParameters(parameters_);
  ROS_INFO_NAMED(private_node_.getNamespace(),
                 "%s: reconfigured (from the next request): default_utility %s, occluder_radius "
                 "%g, belief_samples_per_component %d",
                 private_node_.getNamespace().c_str(), config.default_utility.c_str(),
                 config.occluder_radius, config.belief_samples_per_component);
}

void InformativenessServerRos::publishScoreTopics() {
  const ModelBundle& model = requests_->model();
  const Eigen::VectorXf& g = model.global_scores;
  heatmap_msg_ = colouredSurface(model, g, medianOfValid(g), parameters_.object_frame);
  heatmap_publisher_.publish(heatmap_msg_);

  // One sphere per training direction on a sphere around the object, coloured by its view score
  // on the same scale (white = most informative), and text labels on the best ones.
  const auto& informativeness = model.view_informativeness;
  const Eigen::VectorXf view_scores = informativeness.view_scores.cast<float>();
  const double black_at = medianOfValid(view_scores);
  visualization_msgs::MarkerArray markers;
  visualization_msgs::Marker sphere;
  sphere.header.frame_id = parameters_.object_frame;
  sphere.ns = "view_scores";
  sphere.type = visualization_msgs::Marker::SPHERE;
  sphere.action = visualization_msgs::Marker::ADD;
  sphere.pose.orientation.w = 1.0;
  sphere.scale.x = sphere.scale.y = sphere.scale.z = 0.015;
  for (int m = 0; m < requests_->scorer().viewCount(); ++m) {
    sphere.id = m;
    sphere.pose.position = tf2::toMsg(
        Eigen::Vector3d(parameters_.view_marker_distance * model.view_directions[m].normalized()));
    sphere.color = toColour(heatmapColour(view_scores(m), black_at));
    markers.markers.push_back(sphere);
  }
  visualization_msgs::Marker label = sphere;
  label.ns = "best_views";
  label.type = visualization_msgs::Marker::TEXT_VIEW_FACING;
  label.scale.x = label.scale.y = 0.0;
  label.scale.z = 0.012;  // text height [m]
  label.color = toColour({230, 60, 30});
  const int labelled = std::min<int>(parameters_.label_best, informativeness.ranking.size());
  for (int rank = 0; rank < labelled; ++rank) {
    const int m = informativeness.ranking[rank];
    char text[64];
    std::snprintf(text, sizeof(text), "#%d view %d (%.2f)", rank + 1, m, view_scores(m));
    label.id = rank;
    label.text = text;
    label.pose.position = tf2::toMsg(Eigen::Vector3d((parameters_.view_marker_distance + 0.02) *
                                                     model.view_directions[m].normalized()));
    markers.markers.push_back(label);
  }
  view_scores_msg_ = markers;
  view_scores_publisher_.publish(view_scores_msg_);
}

void InformativenessServerRos::receiveEstimate(
    const view_direction_classification::BinghamMixture::ConstPtr& msg) {
  try {
    requests_->receiveEstimate(*msg);
  } catch (const std::exception& error) {
    ROS_WARN_THROTTLE_NAMED(5.0, private_node_.getNamespace(), "Ignoring an estimate: %s",
                            error.what());
  }
}

void InformativenessServerRos::receiveInstances(
    const view_direction_classification::ObjectInstances::ConstPtr& msg) {
  try {
    requests_->receiveInstances(*msg);
  } catch (const std::exception& error) {
    ROS_WARN_THROTTLE_NAMED(5.0, private_node_.getNamespace(), "Ignoring instances: %s",
                            error.what());
  }
}

Eigen::Isometry3d InformativenessServerRos::lookupFixedFrom(const std::string& frame,
                                                            const char* what) const {
  try {
    return toIsometry(tf_buffer_.lookupTransform(parameters_.fixed_frame, frame, ros::Time(0),
                                                 ros::Duration(parameters_.tf_timeout)));
  } catch (const tf2::TransformException& error) {
    throw Error(std::string("The ") + what + " are in frame '" + frame +
                "', which tf cannot transform into the fixed frame '" + parameters_.fixed_frame +
                "': " + error.what());
  }
}

bool InformativenessServerRos::getHeatmap(GetHeatmap::Request& request,
                                          GetHeatmap::Response& response) {
  requests_->getHeatmap(request, response);
  return true;
}

bool InformativenessServerRos::nextBestView(GetNextBestView::Request& request,
                                            GetNextBestView::Response& response) {
  requests_->nextBestView(request, response);
  return true;
}

}  // namespace vdc
