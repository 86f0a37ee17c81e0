#include "../ros/simulated_depth_camera_ros.h"
#include "view_direction_classification/ros/run_node.h"

int main(int argc, char** argv) {
  return vdc::runNode<vdc::SimulatedDepthCameraRos>(argc, argv, "simulated_depth_camera");
}
