#pragma once

// Test helpers for the orientation_estimator rostests: render the mug at known camera poses and
// publish cloud + camera tf as a depth camera would, and collect the node's estimates.

#include <geometry_msgs/TransformStamped.h>
#include <pcl_conversions/pcl_conversions.h>
#include <ros/ros.h>
#include <sensor_msgs/PointCloud2.h>
#include <tf2_eigen/tf2_eigen.h>
#include <tf2_msgs/TFMessage.h>
#include <view_direction_classification/BinghamMixture.h>

#include <Eigen/Geometry>
#include <mutex>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "view_direction_classification/geometry/camera.h"
#include "view_direction_classification/geometry/depth_renderer.h"
#include "view_direction_classification/geometry/mesh_io.h"

namespace vdc {

constexpr const char* kFixedFrame = "world";
constexpr const char* kCameraFrame = "camera_optical_frame";

// Waits until `publisher` has a subscriber; false after `timeout` s.
inline bool waitForSubscriber(const ros::Publisher& publisher, double timeout) {
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(timeout);
  while (ros::ok() && publisher.getNumSubscribers() == 0) {
    if (ros::WallTime::now() > deadline) return false;
    ros::WallDuration(0.05).sleep();
  }
  return true;
}

// Renders the mesh placed at world_from_object and publishes, per view, the camera's tf
// (world -> camera_optical_frame) and then its cloud on `topic`, both with the view's stamp.
// It publishes /tf itself (not through a tf2_ros::TransformBroadcaster) so that it can wait for
// the estimator's tf listener to connect: a transform sent before that is lost.
class MugViewPublisher {
 public:
  MugViewPublisher(ros::NodeHandle& node, const std::string& mesh_path,
                   const Eigen::Isometry3d& world_from_object, const std::string& topic = "cloud")
      : renderer_(loadMesh(mesh_path)),
        world_from_object_(world_from_object),
        publisher_(node.advertise<sensor_msgs::PointCloud2>(topic, 10)),
        tf_publisher_(node.advertise<tf2_msgs::TFMessage>("/tf", 100)) {}

  ros::Publisher& publisher() { return publisher_; }

  // True once the estimator subscribes to the clouds and some tf listener to /tf.
  bool waitUntilConnected(double timeout) {
    return waitForSubscriber(publisher_, timeout) && waitForSubscriber(tf_publisher_, timeout);
  }

  // The camera sees the object from `direction` (object frame) at `distance` with `roll`.
  void publishView(const Eigen::Vector3d& direction, double distance, double roll,
                   const ros::Time& stamp, unsigned noise_seed) {
    const Eigen::Isometry3d camera_from_object = cameraFromObject(direction, distance, roll);
    std::mt19937 rng(noise_seed);
    pcl::PointCloud<pcl::PointXYZ> cloud =
        renderer_.render(camera_from_object, DepthNoiseModel{true}, &rng);
    publishTransform(world_from_object_ * camera_from_object.inverse(), stamp);
    // The tf message must be in the estimator's buffer before it looks the cloud up.
    ros::WallDuration(0.05).sleep();
    sensor_msgs::PointCloud2 msg;
    pcl::toROSMsg(cloud, msg);
    msg.header.frame_id = kCameraFrame;
    msg.header.stamp = stamp;
    publisher_.publish(msg);
  }

  void publishTransform(const Eigen::Isometry3d& world_from_camera, const ros::Time& stamp,
                        const std::string& camera_frame = kCameraFrame) {
    geometry_msgs::TransformStamped transform = tf2::eigenToTransform(world_from_camera);
    transform.header.frame_id = kFixedFrame;
    transform.header.stamp = stamp;
    transform.child_frame_id = camera_frame;
    tf2_msgs::TFMessage message;
    message.transforms.push_back(transform);
    tf_publisher_.publish(message);
  }

 private:
  DepthRenderer renderer_;
  Eigen::Isometry3d world_from_object_;
  ros::Publisher publisher_, tf_publisher_;
};

// Collects the estimator's ~estimate messages (spun by an AsyncSpinner of the test).
class EstimateRecorder {
 public:
  EstimateRecorder(ros::NodeHandle& node, const std::string& topic)
      : subscriber_(node.subscribe(topic, 100, &EstimateRecorder::callback, this)) {}

  // True once the estimator's publisher is connected (estimates sent before that are lost).
  bool waitUntilConnected(double timeout) {
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(timeout);
    while (ros::ok() && subscriber_.getNumPublishers() == 0) {
      if (ros::WallTime::now() > deadline) return false;
      ros::WallDuration(0.05).sleep();
    }
    return true;
  }

  std::size_t count() {
    std::lock_guard<std::mutex> lock(mutex_);
    return estimates_.size();
  }

  // The estimate with this stamp, waiting up to `timeout` seconds for it.
  std::optional<view_direction_classification::BinghamMixture> waitFor(const ros::Time& stamp,
                                                                       double timeout) {
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(timeout);
    while (ros::ok() && ros::WallTime::now() < deadline) {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        for (const auto& estimate : estimates_) {
          if (estimate.header.stamp == stamp) return estimate;
        }
      }
      ros::WallDuration(0.02).sleep();
    }
    return std::nullopt;
  }

 private:
  void callback(const view_direction_classification::BinghamMixture& estimate) {
    std::lock_guard<std::mutex> lock(mutex_);
    estimates_.push_back(estimate);
  }

  std::mutex mutex_;
  std::vector<view_direction_classification::BinghamMixture> estimates_;
  ros::Subscriber subscriber_;
};

}  // namespace vdc
