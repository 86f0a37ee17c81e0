#pragma once

#include <ros/node_handle.h>

#include <memory>
#include <string>

#include "orientation_estimator_ros.h"
#include "scene_estimator_ros.h"

namespace vdc {

// The orientation_estimator node and nodelet: with ~models (a model library) or segmentation
// `scene` or `labels` (a library of one, ~model) every known object of the scene
// (SceneEstimatorRos, `labels`: the objects of a detector's label image), else
// the one object of ~model with segmentation none, region_of_interest or tabletop
// (OrientationEstimatorRos). Throws what the chosen class throws at start-up.
class EstimatorShell {
 public:
  EstimatorShell(ros::NodeHandle node, ros::NodeHandle private_node) {
    std::string segmentation;
    private_node.getParam("segmentation", segmentation);
    if (private_node.hasParam("models") || segmentation == "scene" || segmentation == "labels") {
      scene_ = std::make_unique<SceneEstimatorRos>(node, private_node);
    } else {
      single_ = std::make_unique<OrientationEstimatorRos>(node, private_node);
    }
  }

 private:
  std::unique_ptr<OrientationEstimatorRos> single_;
  std::unique_ptr<SceneEstimatorRos> scene_;
};

}  // namespace vdc
