#pragma once

#include <ros/node_handle.h>

#include <string>

#include "view_direction_classification/estimation/orientation_estimator.h"
#include "view_direction_classification/ros/parameter_table.h"

namespace vdc {

// Everything the orientation_estimator node reads from its private parameters
// (config/estimator.yaml documents each one; doc/nodes.md lists them).
struct EstimatorRosParameters {
  std::string model_path;               // model bundle (.h5), required
  std::string fixed_frame = "world";    // frame of the estimate (the object must be static in it)
  std::string object_id = "object";     // copied into every estimate
  std::string object_frame = "object";  // tf child frame broadcast when publish_tf
  bool publish_tf = true;
  // [Hz] re-broadcast of the latest object tf with fresh stamps (/tf is not latched: rviz or a
  // listener started after an estimate would never learn the frame); 0 = only on each estimate.
  double tf_rate = 10.0;
  double tf_timeout = 0.2;  // [s] wait for the camera pose at the cloud's stamp
  int max_points = 500000;  // larger clouds are skipped (latency guard)
  // [m^2] per axis in ~pose's covariance when the position is not a refined one (refinement
  // none, or nothing verified yet); a refined position carries its fit's covariance.
  double position_variance = 0.0025;
  int marker_samples = 20;     // axes triads sampled from the belief for ~markers
  double marker_length = 0.1;  // [m] MAP axes arrows; samples are drawn at 0.8 of it
  // [deg] ~estimate's `converged` when its cone90_deg is at most this.
  double converged_cone90_deg = 15.0;
  // Core settings; segmentation.roi_centre holds the region of interest in the FIXED frame (the
  // node moves it into each cloud's frame).
  EstimatorParameters core;
};

// The estimator's parameters: names, fields and rules (estimator_ros_parameters.cpp).
const ParameterTable<EstimatorRosParameters>& estimatorParameterTable();

// Reads and validates the parameters of `private_node`. Throws vdc::Error naming the parameter
// (e.g. "Parameter ~tf_timeout must be a finite number >= 0, got -1.") for a missing model, a
// wrong type, an unknown segmentation mode or an out-of-range value.
// With a model library (~models set, scene_ros_parameters.h) ~model is not required.
EstimatorRosParameters readEstimatorRosParameters(const ros::NodeHandle& private_node,
                                                  bool with_library = false);

}  // namespace vdc
