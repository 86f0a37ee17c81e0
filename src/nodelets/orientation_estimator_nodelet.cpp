#include <pluginlib/class_list_macros.hpp>

#include "../ros/estimator_shell.h"
#include "view_direction_classification/ros/shell_nodelet.h"

namespace vdc {

// The orientation_estimator as a nodelet: beside a camera driver in one manager, clouds arrive
// without serialisation.
class OrientationEstimatorNodelet : public ShellNodelet<EstimatorShell> {};

}  // namespace vdc

PLUGINLIB_EXPORT_CLASS(vdc::OrientationEstimatorNodelet, nodelet::Nodelet)
