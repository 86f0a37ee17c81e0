#include "simulated_depth_camera_ros.h"

#include <geometry_msgs/TransformStamped.h>
#include <pcl_conversions/pcl_conversions.h>
#include <sensor_msgs/PointCloud2.h>
#include <tf2_eigen/tf2_eigen.h>

#include <boost/make_shared.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>

#include "view_direction_classification/common/error.h"
#include "view_direction_classification/common/quaternion.h"
#include "view_direction_classification/geometry/camera.h"
#include "view_direction_classification/geometry/mesh_io.h"
#include "view_direction_classification/geometry/mug_mesh.h"
#include "view_direction_classification/geometry/scene.h"
#include "view_direction_classification/geometry/visibility_crop.h"

namespace vdc {
namespace {

// Object pose from [x, y, z, roll, pitch, yaw] (rotation R = Rz(yaw) Ry(pitch) Rx(roll), the
// REP 103 fixed-axis convention).
Eigen::Isometry3d poseFromXyzRpy(const std::vector<double>& v) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = Eigen::Vector3d(v[0], v[1], v[2]);
  pose.linear() = (Eigen::AngleAxisd(v[5], Eigen::Vector3d::UnitZ()) *
                   Eigen::AngleAxisd(v[4], Eigen::Vector3d::UnitY()) *
                   Eigen::AngleAxisd(v[3], Eigen::Vector3d::UnitX()))
                      .toRotationMatrix();
  return pose;
}

geometry_msgs::TransformStamped toTransformMsg(const Eigen::Isometry3d& parent_from_child,
                                               const std::string& parent, const std::string& child,
                                               const ros::Time& stamp) {
  geometry_msgs::TransformStamped msg = tf2::eigenToTransform(parent_from_child);
  msg.header.stamp = stamp;
  msg.header.frame_id = parent;
  msg.child_frame_id = child;
  return msg;
}

// The renderer of the parts present and the table (table: empty for none), all in the fixed
// frame in one z-buffer, so that they hide each other; null when nothing is left to render.
std::shared_ptr<const DepthRenderer> sceneRenderer(const std::vector<ScenePart>& parts,
                                                   const std::vector<bool>& present,
                                                   const std::optional<ScenePart>& table) {
  std::vector<ScenePart> shown;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (present[i]) shown.push_back(parts[i]);
  }
  if (table) shown.push_back(*table);
  if (shown.empty()) return nullptr;
  return std::make_shared<const DepthRenderer>(partsMesh(shown));
}

}  // namespace

SimulatedDepthCameraRos::SimulatedDepthCameraRos(ros::NodeHandle node, ros::NodeHandle private_node)
    : node_(node), private_node_(private_node) {
  const SimulatedDepthCameraRosParameters p = readSimulatedDepthCameraRosParameters(private_node_);
  fixed_frame_ = p.fixed_frame;
  camera_frame_ = p.camera_frame;
  object_frame_ = p.object_frame;
  publish_object_tf_ = p.publish_object_tf;
  Scene scene;
  scene.object = {p.mesh == "mug" ? makeMug() : loadMesh(p.mesh), poseFromXyzRpy(p.object_pose)};
  if (p.table_size[0] > 0.0) scene.table_size = Eigen::Vector2d(p.table_size[0], p.table_size[1]);
  const std::vector<std::string> distractors = distractorDescriptions(p.distractors);
  for (std::size_t i = 0; i < distractors.size(); ++i) {
    const std::vector<double> pose(p.distractor_poses.begin() + 6 * i,
                                   p.distractor_poses.begin() + 6 * (i + 1));
    scene.distractors.push_back({distractorMesh(distractors[i]), poseFromXyzRpy(pose)});
  }
  if (scene.table_size) table_ = tablePart(scene);
  parts_ = {scene.object};
  parts_.insert(parts_.end(), scene.distractors.begin(), scene.distractors.end());
  present_.assign(parts_.size(), true);
  renderer_ = sceneRenderer(parts_, present_, table_);
  noise_.enabled = p.noise;
  rng_.seed(static_cast<std::uint32_t>(p.seed));
  visibility_radius_ = p.visibility_radius;
  for (std::size_t i = 0; i < p.visibility_anchors.size(); i += 3) {
    visibility_anchors_.emplace_back(p.visibility_anchors[i], p.visibility_anchors[i + 1],
                                     p.visibility_anchors[i + 2]);
  }
  if (visibility_anchors_.empty()) visibility_anchors_ = mugHandleAnchors();
  const Eigen::Vector3d direction(p.view_direction[0], p.view_direction[1], p.view_direction[2]);
  world_from_camera_ =
      parts_[0].world_from_part * cameraFromObject(direction, p.distance, p.roll).inverse();

  cloud_publisher_ = private_node_.advertise<sensor_msgs::PointCloud2>("cloud", 1);
  move_service_ = private_node_.advertiseService("move_to", &SimulatedDepthCameraRos::moveTo, this);
  place_service_ =
      private_node_.advertiseService("place_part", &SimulatedDepthCameraRos::placePart, this);
  timer_ =
      node_.createTimer(ros::Duration(1.0 / p.rate), &SimulatedDepthCameraRos::publishView, this);
  ROS_INFO_NAMED(
      private_node_.getNamespace(),
      "Simulated depth camera: mesh %s%s, %zu distractors, %s -> %s at %.1f Hz, noise %s, "
      "visibility crop %s",
      p.mesh.c_str(), scene.table_size ? " on a table" : "", distractors.size(),
      fixed_frame_.c_str(), camera_frame_.c_str(), p.rate, noise_.enabled ? "on" : "off",
      visibility_radius_ > 0.0 ? (std::to_string(visibility_radius_) + " m").c_str() : "off");
}

void SimulatedDepthCameraRos::publishView(const ros::TimerEvent&) {
  Eigen::Isometry3d world_from_camera, world_from_object;
  bool object_present = false;
  std::shared_ptr<const DepthRenderer> renderer;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    world_from_camera = world_from_camera_;
    world_from_object = parts_[0].world_from_part;
    object_present = present_[0];
    renderer = renderer_;
  }
  const ros::Time stamp = ros::Time::now();
  // The tf goes out even when nobody listens to the cloud: the estimator needs it to place the
  // cloud, and an rviz user sees where the camera is.
  std::vector<geometry_msgs::TransformStamped> transforms = {
      toTransformMsg(world_from_camera, fixed_frame_, camera_frame_, stamp)};
  if (publish_object_tf_ && object_present) {
    transforms.push_back(toTransformMsg(world_from_object, fixed_frame_, object_frame_, stamp));
  }
  tf_broadcaster_.sendTransform(transforms);
  if (cloud_publisher_.getNumSubscribers() == 0) return;  // rendering costs; skip it unheard

  const Eigen::Isometry3d camera_from_world = world_from_camera.inverse();
  pcl::PointCloud<pcl::PointXYZ> cloud;
  if (renderer) {
    cloud = renderer->render(camera_from_world, noise_, &rng_);
  } else {  // nothing left in the scene: every pixel sees nothing
    const CameraIntrinsics intrinsics;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    cloud = pcl::PointCloud<pcl::PointXYZ>(static_cast<std::uint32_t>(intrinsics.width),
                                           static_cast<std::uint32_t>(intrinsics.height),
                                           pcl::PointXYZ(nan, nan, nan));
    cloud.is_dense = false;
  }
  if (visibility_radius_ > 0.0) {
    const Eigen::Isometry3d camera_from_object = camera_from_world * world_from_object;
    cloud = cropToAnchors(cloud, camera_from_object, visibility_anchors_, visibility_radius_);
  }
  // A fresh message for every frame, handed over as a shared pointer and never touched again:
  // a subscriber in the same nodelet manager receives this very object (no serialisation, no
  // copy); published by reference, roscpp would serialise it and every in-process subscriber
  // would get a deserialised copy of ~3.7 MB.
  const sensor_msgs::PointCloud2Ptr msg = boost::make_shared<sensor_msgs::PointCloud2>();
  pcl::toROSMsg(cloud, *msg);
  msg->header.stamp = stamp;
  msg->header.frame_id = camera_frame_;
  cloud_publisher_.publish(msg);
}

bool SimulatedDepthCameraRos::moveTo(
    view_direction_classification::MoveCamera::Request& request,
    view_direction_classification::MoveCamera::Response& response) {
  using Request = view_direction_classification::MoveCamera::Request;
  try {
    Eigen::Isometry3d world_from_camera = Eigen::Isometry3d::Identity();
    if (request.mode == Request::MODE_POSE) {
      const auto& p = request.pose.position;
      const auto& q = request.pose.orientation;
      const Eigen::Vector3d position(p.x, p.y, p.z);
      const Eigen::Quaterniond rotation(q.w, q.x, q.y, q.z);
      if (!position.allFinite()) throw Error("The camera position is not finite.");
      if (!isUnitQuaternion(Eigen::Vector4d(q.w, q.x, q.y, q.z), kRequestQuaternionTolerance)) {
        throw Error("The camera orientation is not a unit quaternion (norm " +
                    std::to_string(rotation.norm()) + ").");
      }
      world_from_camera.translation() = position;
      world_from_camera.linear() = rotation.normalized().toRotationMatrix();
    } else if (request.mode == Request::MODE_DIRECTION) {
      const Eigen::Vector3d direction(request.direction.x, request.direction.y,
                                      request.direction.z);
      Eigen::Isometry3d world_from_object;
      {
        std::lock_guard<std::mutex> lock(mutex_);
        world_from_object = parts_[0].world_from_part;
      }
      world_from_camera =
          world_from_object * cameraFromObject(direction, request.distance, request.roll).inverse();
    } else {
      throw Error("Unknown mode " + std::to_string(int(request.mode)) +
                  ": use MODE_POSE (0) or MODE_DIRECTION (1).");
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      world_from_camera_ = world_from_camera;
    }
    response.success = true;
    response.message = "Camera moved.";
  } catch (const std::exception& error) {
    response.success = false;
    response.message = error.what();
  }
  return true;
}

bool SimulatedDepthCameraRos::placePart(
    view_direction_classification::PlacePart::Request& request,
    view_direction_classification::PlacePart::Response& response) {
  try {
    std::lock_guard<std::mutex> lock(mutex_);
    if (request.part >= parts_.size()) {
      const std::string distractors = std::to_string(parts_.size() - 1);
      throw Error("No part " + std::to_string(request.part) + ": the scene has the object (0)" +
                  (parts_.size() > 1 ? " and distractors 1 to " + distractors : " only") + ".");
    }
    std::vector<ScenePart> parts = parts_;
    std::vector<bool> present = present_;
    present[request.part] = request.present;
    if (request.present) {
      const auto& p = request.pose.position;
      const auto& q = request.pose.orientation;
      if (!Eigen::Vector3d(p.x, p.y, p.z).allFinite()) {
        throw Error("The part's position is not finite.");
      }
      if (!isUnitQuaternion(Eigen::Vector4d(q.w, q.x, q.y, q.z), kRequestQuaternionTolerance)) {
        throw Error("The part's orientation is not a unit quaternion.");
      }
      Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
      pose.translation() = Eigen::Vector3d(p.x, p.y, p.z);
      pose.linear() = Eigen::Quaterniond(q.w, q.x, q.y, q.z).normalized().toRotationMatrix();
      parts[request.part].world_from_part = pose;
    }
    // Built before anything changes: a renderer that cannot be built leaves the scene as it was.
    std::shared_ptr<const DepthRenderer> renderer = sceneRenderer(parts, present, table_);
    parts_ = std::move(parts);
    present_ = std::move(present);
    renderer_ = std::move(renderer);
    response.success = true;
    response.message = request.present ? "Part placed." : "Part taken away.";
  } catch (const std::exception& error) {
    response.success = false;
    response.message = error.what();
  }
  return true;
}

}  // namespace vdc
