#pragma once

#include <ros/node_handle.h>

#include <string>
#include <utility>
#include <vector>

namespace vdc {

// ~models, the model library of the orientation_estimator and the informativeness_server: a map
// from a model's name to its bundle's path, in the map's (name) order. Read outside the nodes'
// parameter tables (a map is not one of their types). Throws vdc::Error naming ~models if it is
// unset or not a non-empty map from names to non-empty strings.
std::vector<std::pair<std::string, std::string>> readModelsParameter(
    const ros::NodeHandle& private_node);

}  // namespace vdc
