#include <pluginlib/class_list_macros.hpp>

#include "../ros/informativeness_server_ros.h"
#include "view_direction_classification/ros/shell_nodelet.h"

namespace vdc {

// The informativeness server as a nodelet, beside the estimator in one manager.
class InformativenessServerNodelet : public ShellNodelet<InformativenessServerRos> {};

}  // namespace vdc

PLUGINLIB_EXPORT_CLASS(vdc::InformativenessServerNodelet, nodelet::Nodelet)
