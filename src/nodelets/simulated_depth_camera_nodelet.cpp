#include <pluginlib/class_list_macros.hpp>

#include "../ros/simulated_depth_camera_ros.h"
#include "view_direction_classification/ros/shell_nodelet.h"

namespace vdc {

// The simulated camera as a nodelet, so an estimator nodelet in the same manager gets its clouds
// without a copy.
class SimulatedDepthCameraNodelet : public ShellNodelet<SimulatedDepthCameraRos> {};

}  // namespace vdc

PLUGINLIB_EXPORT_CLASS(vdc::SimulatedDepthCameraNodelet, nodelet::Nodelet)
