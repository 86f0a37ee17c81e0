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
  // parameters (n_feat, kappa, refinement, frame selection ...). Its label_models is ~label_models
  // (read outside the table: a map).
  SceneEstimatorParameters scene;
  // segmentation `labels`: a cloud takes the label image whose stamp is within this [s] of its
  // own (0: the same stamp), waiting up to labels_timeout [s] for it (a detector is often
  // slower than the camera).
  double labels_stamp_tolerance = 0.0;
  double labels_timeout = 0.2;
  // The object memory (recognition/scene_memory_file.h): loaded at start-up when it exists,
  // saved at shutdown and on ~save_memory. Empty: nothing outlives the node.
  std::string memory_file;
  // ~memory_markers: a remembered instance's markers fade by half (above a floor) every this
  // many seconds since it was last seen.
  double memory_fade_age = 60.0;
};

// The scene settings' names, fields and rules (scene_ros_parameters.cpp).
const ParameterTable<SceneRosParameters>& sceneParameterTable();
// The table's names, ~models and ~label_models: every parameter a library needs.
std::vector<std::string> sceneParameterNames();

// Reads ~models, ~label_models and the scene table. Without ~models (segmentation `scene` or
// `labels` with one ~model) the library is that model, named `object_id`. Throws vdc::Error
// naming the parameter for a ~models that is not a non-empty map from names to non-empty
// strings, a ~label_models that is not a map from class ids (non-negative integers, written as
// strings) to model names, a missing model, or a bad scene setting.
SceneRosParameters readSceneRosParameters(const ros::NodeHandle& private_node,
                                          const EstimatorRosParameters& estimator);

}  // namespace vdc
