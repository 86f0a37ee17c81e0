#pragma once

#include <ros/node_handle.h>

#include <string>
#include <utility>
#include <vector>

#include "estimator_ros_parameters.h"
#include "view_direction_classification/recognition/scene_estimator.h"
#include "view_direction_classification/ros/parameter_table.h"

namespace vdc {

// What the orientation_estimator reads besides its own parameters when it is given a model
// library (~models): every known object of the scene (doc/nodes.md, "Several objects").
struct SceneRosParameters {
  // ~models: a map from a name to a model bundle's path (read outside the table: a map).
  std::vector<std::pair<std::string, std::string>> models;
  // The scene layer's settings; its `instance` estimator settings come from the estimator's own
  // parameters (n_feat, kappa, refinement, frame selection ...).
  SceneEstimatorParameters scene;
};

// The scene settings' names, fields and rules (scene_ros_parameters.cpp).
const ParameterTable<SceneRosParameters>& sceneParameterTable();
// The table's names and ~models: every parameter a library needs.
std::vector<std::string> sceneParameterNames();

// Reads ~models and the scene table. Without ~models (segmentation `scene` with one ~model) the
// library is that model, named `object_id`. Throws vdc::Error naming the parameter for a
// ~models that is not a non-empty map from names to non-empty strings, a missing model, or a bad
// scene setting.
SceneRosParameters readSceneRosParameters(const ros::NodeHandle& private_node,
                                          const EstimatorRosParameters& estimator);

}  // namespace vdc
