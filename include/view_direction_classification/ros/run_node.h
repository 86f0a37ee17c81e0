#pragma once

#include <ros/ros.h>

#include <exception>
#include <string>

namespace vdc {

// The body of every node binary: runs one `...Ros` class (the same class its nodelet wraps) in
// its own process. RosClass(ros::NodeHandle node, ros::NodeHandle private_node) sets up
// everything and throws on a fatal start-up problem (e.g. a missing or corrupt model bundle);
// that is reported as one ROS_FATAL line and the process exits with status 1, so roslaunch shows
// the reason instead of a crash loop. The shell logs to the logger named after the node (its
// private namespace), as its nodelet logs with NODELET_* to the one named after the nodelet.
// ros::spin() runs every callback on this thread, one at a time.
template <typename RosClass>
int runNode(int argc, char** argv, const std::string& default_name) {
  ros::init(argc, argv, default_name);
  ros::NodeHandle node;
  ros::NodeHandle private_node("~");
  try {
    RosClass instance(node, private_node);
    ros::spin();
  } catch (const std::exception& error) {
    ROS_FATAL_NAMED(ros::this_node::getName(), "%s: %s", ros::this_node::getName().c_str(),
                    error.what());
    return 1;
  }
  return 0;
}

}  // namespace vdc
