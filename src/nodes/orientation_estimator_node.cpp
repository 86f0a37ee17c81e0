#include "../ros/orientation_estimator_ros.h"
#include "view_direction_classification/ros/run_node.h"

int main(int argc, char** argv) {
  return vdc::runNode<vdc::OrientationEstimatorRos>(argc, argv, "orientation_estimator");
}
