#include "../ros/estimator_shell.h"
#include "view_direction_classification/ros/run_node.h"

int main(int argc, char** argv) {
  return vdc::runNode<vdc::EstimatorShell>(argc, argv, "orientation_estimator");
}
