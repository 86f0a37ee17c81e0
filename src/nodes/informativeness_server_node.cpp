#include "../ros/informativeness_server_ros.h"
#include "view_direction_classification/ros/run_node.h"

int main(int argc, char** argv) {
  return vdc::runNode<vdc::InformativenessServerRos>(argc, argv, "informativeness_server");
}
