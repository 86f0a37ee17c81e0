#pragma once

#include <ros/node_handle.h>

#include <string>
#include <utility>
#include <vector>

#include "view_direction_classification/planning/next_best_view.h"
#include "view_direction_classification/ros/parameter_table.h"

namespace vdc {

// Everything the informativeness_server node reads from its private parameters
// (config/informativeness_server.yaml documents each one).
struct InformativenessServerRosParameters {
  std::string model_path;  // model bundle (.h5) of the one object; required without `models`
  // ~models: the library the instances' requests are planned with, a map from a name (an
  // ObjectInstance's `model`) to a bundle's path (read outside the table: a map). Empty if unset.
  std::vector<std::pair<std::string, std::string>> models;
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
// The table's names and ~models: every parameter the server reads.
std::vector<std::string> informativenessServerParameterNames();

// Reads and validates the parameters of `private_node` (~model is not required when ~models is
// set); throws vdc::Error naming the parameter.
InformativenessServerRosParameters readInformativenessServerRosParameters(
    const ros::NodeHandle& private_node);

}  // namespace vdc
