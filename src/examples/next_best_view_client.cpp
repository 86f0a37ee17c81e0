// Asks the informativeness server where to look next and prints the answer: the C++ twin of
// scripts/examples/next_best_view_client.py (README, "Your object, your camera"). Built with the
// package so that it always compiles against the current service definition.
//   rosrun view_direction_classification next_best_view_client _utility:=information_gain
#include <ros/ros.h>

#include <string>

#include "view_direction_classification/GetNextBestView.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "next_best_view_client");
  ros::NodeHandle private_node("~");
  const std::string service = "informativeness_server/next_best_view";
  if (!ros::service::waitForService(service, ros::Duration(30.0))) {
    ROS_FATAL("No service %s within 30 s: is informativeness_server running?", service.c_str());
    return 1;
  }

  // No candidates given: the server samples them around the object. The belief is the
  // estimator's latest ~estimate, which the server tracks (use_belief = false).
  view_direction_classification::GetNextBestView call;
  call.request.utility = private_node.param<std::string>("utility", "information_gain");
  call.request.sample_count = private_node.param("sample_count", 50);
  call.request.sample_distance = private_node.param("sample_distance", 0.6);
  if (!ros::service::call(service, call)) {
    ROS_FATAL("Calling %s failed.", service.c_str());
    return 1;
  }
  const auto& response = call.response;
  if (!response.success) {
    ROS_ERROR("next_best_view refused the request: %s", response.message.c_str());
    return 1;
  }

  const auto& p = response.best.pose.position;
  const auto& q = response.best.pose.orientation;
  ROS_INFO(
      "best of %zu candidates (utility %s = %.3f): camera at (%.3f, %.3f, %.3f) in %s, "
      "optical-frame orientation (x y z w) (%.3f, %.3f, %.3f, %.3f)",
      response.ranked.poses.size(), call.request.utility.c_str(), response.utilities[0], p.x, p.y,
      p.z, response.best.header.frame_id.c_str(), q.x, q.y, q.z, q.w);
  ROS_INFO("server: %s", response.message.c_str());
  return 0;
}
