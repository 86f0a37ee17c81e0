#pragma once

#include <ros/node_handle.h>

#include <string>
#include <vector>

#include "view_direction_classification/ros/parameter_table.h"

namespace vdc {

// Everything the simulated_depth_camera node reads from its private parameters
// (config/simulated_depth_camera.yaml documents each one).
struct SimulatedDepthCameraRosParameters {
  std::string mesh = "mug";  // a mesh file in metres, or "mug" for the built-in mug
  std::string fixed_frame = "world";
  std::string camera_frame = "camera_optical_frame";
  std::string object_frame = "object_ground_truth";
  bool publish_object_tf = true;
  std::vector<double> object_pose = {0.0, 0.0, 0.0, 0.0, 0.0, 0.0};  // x y z roll pitch yaw
  double rate = 2.0;                                                 // [Hz]
  std::vector<double> view_direction = {1.0, 0.0, 0.5};  // object frame, any non-zero length
  double distance = 0.6;                                 // [m]
  double roll = 0.0;                                     // [rad]
  bool noise = true;
  int seed = 1;
  double visibility_radius = 0.0;          // [m]; 0 = no crop
  std::vector<double> visibility_anchors;  // x y z triples; empty = the mug's handle
  // The scene around the object (geometry/scene.h): a table under it of this size [m] along the
  // fixed frame's x and y ([0, 0]: none), and distractors: descriptions separated by ';' ("box
  // SX SY SZ", "cylinder R H" or a mesh file) with one x y z roll pitch yaw pose each.
  std::vector<double> table_size = {0.0, 0.0};
  std::string distractors;
  std::vector<double> distractor_poses;
};

// The descriptions in `distractors`, trimmed, empty ones dropped.
std::vector<std::string> distractorDescriptions(const std::string& distractors);

// The camera's parameters: names, fields and rules (simulated_depth_camera_ros_parameters.cpp).
const ParameterTable<SimulatedDepthCameraRosParameters>& simulatedDepthCameraParameterTable();

// Reads and validates the parameters of `private_node`; throws vdc::Error naming the parameter.
SimulatedDepthCameraRosParameters readSimulatedDepthCameraRosParameters(
    const ros::NodeHandle& private_node);

}  // namespace vdc
