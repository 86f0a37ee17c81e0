#pragma once

#include <ros/node_handle.h>

#include <string>

#include "view_direction_classification/planning/next_best_view.h"
#include "view_direction_classification/ros/parameter_table.h"

namespace vdc {

// Everything the informativeness_server node reads from its private parameters
// (config/informativeness_server.yaml documents each one).
struct InformativenessServerRosParameters {
  std::string model_path;  // model bundle (.h5), required
  std::string fixed_frame = "world";
  std::string object_frame = "object";
  int label_best = 3;                    // text labels on the best directions of ~view_scores
  double view_marker_distance = 0.15;    // [m] radius of the ~view_scores sphere
  double occluder_radius = 0.005;        // [m] line-of-sight clearance (utility informativeness)
  int belief_samples_per_component = 8;  // hypotheses per component (utility information_gain)
  // The utility of a ~next_best_view request that leaves `utility` empty.
  ViewUtility default_utility = ViewUtility::kInformativeness;
  double tf_timeout = 0.2;        // [s]
  double republish_period = 1.0;  // [s] ~heatmap, ~view_scores re-sent; 0 = latched once
};

// The server's parameters: names, fields and rules (informativeness_server_ros_parameters.cpp).
const ParameterTable<InformativenessServerRosParameters>& informativenessServerParameterTable();

// Reads and validates the parameters of `private_node`; throws vdc::Error naming the parameter.
InformativenessServerRosParameters readInformativenessServerRosParameters(
    const ros::NodeHandle& private_node);

}  // namespace vdc
