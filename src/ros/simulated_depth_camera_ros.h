#pragma once

#include <ros/ros.h>
#include <tf2_ros/transform_broadcaster.h>
#include <view_direction_classification/MoveCamera.h>
#include <view_direction_classification/PlacePart.h>

#include <Eigen/Geometry>

#include <memory>
#include <mutex>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "simulated_depth_camera_ros_parameters.h"
#include "view_direction_classification/geometry/depth_noise.h"
#include "view_direction_classification/geometry/depth_renderer.h"
#include "view_direction_classification/geometry/scene.h"

namespace vdc {

// The simulated depth camera node (doc/nodes.md): renders a mesh placed at a fixed
// pose in fixed_frame, optionally on a table among distractors (geometry/scene.h), with the
// training renderer and publishes the organised cloud `~cloud` in
// the camera's optical frame at `rate`, with the camera's tf (fixed_frame -> camera_frame) at the
// same stamp, and optionally the object's ground-truth tf for evaluation. `~move_to` moves it;
// `~place_part` moves, takes away or puts back a part of the scene (a patrol's changes).
// Parameters are documented in config/simulated_depth_camera.yaml.
//
// Each cloud is a new message published as a shared pointer: in a nodelet manager, the
// estimator's nodelet gets the very object rendered here, without serialisation or a copy.
// Threads: the timer and the services are callbacks of one node handle's queue, run one at a
// time: on ros::spin()'s thread in the node, on one of the manager's worker threads in the
// nodelet (a nodelet's getNodeHandle() queue is single-threaded); rendering a frame delays a
// move, and a placed part shows from the next frame on.
class SimulatedDepthCameraRos {
 public:
  // Throws vdc::Error (or std::exception) for invalid parameters or an unreadable mesh.
  SimulatedDepthCameraRos(ros::NodeHandle node, ros::NodeHandle private_node);

 private:
  void publishView(const ros::TimerEvent& event);
  bool moveTo(view_direction_classification::MoveCamera::Request& request,
              view_direction_classification::MoveCamera::Response& response);
  bool placePart(view_direction_classification::PlacePart::Request& request,
                 view_direction_classification::PlacePart::Response& response);

  ros::NodeHandle node_, private_node_;
  std::string fixed_frame_, camera_frame_, object_frame_;
  bool publish_object_tf_ = false;
  DepthNoiseModel noise_;
  std::mt19937 rng_;
  double visibility_radius_ = 0.0;  // <= 0: no crop
  std::vector<Eigen::Vector3d> visibility_anchors_;

  // Guards what the timer reads and the services change. They do not overlap on the
  // single-threaded queues above; the lock keeps that true on a multi-threaded spinner.
  std::mutex mutex_;
  Eigen::Isometry3d world_from_camera_ = Eigen::Isometry3d::Identity();
  // The object first, then the distractors; a part taken away is not present.
  std::vector<ScenePart> parts_;
  std::vector<bool> present_;
  std::optional<ScenePart> table_;  // placed once: it stays when the object moves
  // Of the parts present and the table, in the fixed frame; null: nothing is left to render.
  std::shared_ptr<const DepthRenderer> renderer_;

  ros::Publisher cloud_publisher_;
  ros::ServiceServer move_service_, place_service_;
  tf2_ros::TransformBroadcaster tf_broadcaster_;
  ros::Timer timer_;
};

}  // namespace vdc
