// rostest node of nodelets_closed_loop.test: this process *is* the nodelet manager. It hosts a
// nodelet::Loader with the manager's ROS API (~load_nodelet), so the launch files' `nodelet load`
// (manager:=nodelets_closed_loop) put the camera, the estimator and the server in here, found by
// pluginlib from nodelet_plugins.xml. The test then runs the closed loop (camera -> estimator ->
// ~estimate -> server -> next best view -> camera moves -> a second view fused) and, subscribed
// beside the estimator, checks that the camera's clouds cross the manager without a copy.
#include <gtest/gtest.h>
#include <nodelet/NodeletUnload.h>
#include <nodelet/loader.h>
#include <ros/ros.h>
#include <sensor_msgs/PointCloud2.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>
#include <view_direction_classification/BinghamMixture.h>
#include <view_direction_classification/GetNextBestView.h>
#include <view_direction_classification/MoveCamera.h>

#include <boost/make_shared.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace {

using view_direction_classification::BinghamMixture;
using view_direction_classification::GetNextBestView;
using view_direction_classification::MoveCamera;

const std::string kCloudTopic = "simulated_depth_camera/cloud";
const std::vector<std::string> kNodelets = {"/simulated_depth_camera", "/orientation_estimator",
                                            "/informativeness_server"};

// Counts the clouds this process receives and how many of them roscpp had to create (deserialise)
// for us. A subscriber in the same process as a publisher that hands over a shared pointer gets
// the publisher's own object: the message factory is never called. Published by reference, every
// cloud is serialised and deserialised into a new message made by the factory.
struct CloudCounter {
  std::atomic<int> received{0};
  std::atomic<int> created{0};
};

class ManagerState {
 public:
  void estimate(const BinghamMixture::ConstPtr& msg) {
    std::lock_guard<std::mutex> lock(mutex_);
    latest_ = msg;
  }
  BinghamMixture::ConstPtr latest() {
    std::lock_guard<std::mutex> lock(mutex_);
    return latest_;
  }

 private:
  std::mutex mutex_;
  BinghamMixture::ConstPtr latest_;
};

// Waits until an estimate with at least `views` fused views arrived; nullptr after the timeout.
BinghamMixture::ConstPtr waitForViews(ManagerState& state, std::uint32_t views, double timeout) {
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(timeout);
  while (ros::ok() && ros::WallTime::now() < deadline) {
    const BinghamMixture::ConstPtr latest = state.latest();
    if (latest && latest->views_fused >= views) return latest;
    ros::WallDuration(0.05).sleep();
  }
  return nullptr;
}

// Unloads the nodelets through the manager's ~unload_nodelet service when the test ends (every
// way it ends), as each `nodelet load` process does when it stops: that drops the nodelet's bond
// to that process too. Left to ~Loader, the bonds are broken while the Loader is being destroyed,
// and nodelet's broken-bond callback, on its bond thread, unloads the nodelet from the
// half-destroyed Loader: ThreadSanitizer reported a use after free and a destroyed mutex there,
// and the manager aborted with boost::lock_error (doc/hardening.md, "Threads (TSan)").
// Only the nodelets loaded by then: after a failed start there may be fewer.
class UnloadAtExit {
 public:
  explicit UnloadAtExit(nodelet::Loader& loader) : loader_(loader) {}
  UnloadAtExit(const UnloadAtExit&) = delete;
  UnloadAtExit& operator=(const UnloadAtExit&) = delete;
  ~UnloadAtExit() {
    for (const std::string& name : loader_.listLoadedNodelets()) {
      nodelet::NodeletUnload unload;
      unload.request.name = name;
      if (!ros::service::call("nodelets_closed_loop/unload_nodelet", unload) ||
          !unload.response.success) {
        ADD_FAILURE() << "could not unload " << name << " through ~unload_nodelet";
      }
    }
  }

 private:
  nodelet::Loader& loader_;
};

bool allLoaded(nodelet::Loader& loader) {
  const std::vector<std::string> loaded = loader.listLoadedNodelets();
  return std::all_of(kNodelets.begin(), kNodelets.end(), [&](const std::string& name) {
    return std::find(loaded.begin(), loaded.end(), name) != loaded.end();
  });
}

double angleBetween(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0));
}

TEST(NodeletsClosedLoop, camera_estimator_and_server_in_one_manager_close_the_loop_without_copies) {
  ros::NodeHandle node;
  CloudCounter clouds;
  // Subscribed before any nodelet exists, so this callback is the topic's first in the process.
  ros::SubscribeOptions options;
  options.init<sensor_msgs::PointCloud2>(
      kCloudTopic, 1, [&clouds](const sensor_msgs::PointCloud2ConstPtr&) { ++clouds.received; },
      [&clouds] {
        ++clouds.created;
        return boost::make_shared<sensor_msgs::PointCloud2>();
      });
  ros::Subscriber cloud_subscriber = node.subscribe(options);
  ManagerState state;
  ros::Subscriber estimate_subscriber =
      node.subscribe("orientation_estimator/estimate", 1, &ManagerState::estimate, &state);
  tf2_ros::Buffer tf_buffer;
  tf2_ros::TransformListener tf_listener(tf_buffer);
  ros::AsyncSpinner spinner(2);  // the Loader's services and this test's own subscriptions
  spinner.start();
  nodelet::Loader loader;  // advertises ~load_nodelet: the launch files load into it
  const UnloadAtExit unload_at_exit(loader);  // destroyed before the loader

  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(120.0);
  while (!allLoaded(loader) && ros::WallTime::now() < deadline) ros::WallDuration(0.1).sleep();
  ASSERT_TRUE(allLoaded(loader)) << "the three nodelets were not loaded into this manager";

  // Camera -> estimator -> ~estimate, all in this process.
  const BinghamMixture::ConstPtr first = waitForViews(state, 1, 120.0);
  ASSERT_TRUE(first) << "no estimate from the estimator nodelet";

  // Server: the next best view under the estimator's belief (it came over the in-manager topic).
  GetNextBestView next_best_view;
  next_best_view.request.utility = "information_gain";
  next_best_view.request.sample_count = 30;
  next_best_view.request.sample_distance = 0.6;
  ASSERT_TRUE(ros::service::waitForService("informativeness_server/next_best_view", 30000));
  ASSERT_TRUE(ros::service::call("informativeness_server/next_best_view", next_best_view));
  ASSERT_TRUE(next_best_view.response.success) << next_best_view.response.message;
  EXPECT_NE(next_best_view.response.message.find("Belief from the latest estimate."),
            std::string::npos)
      << next_best_view.response.message;

  // Move there (the best-ranked candidate at least 45 degrees from the current view, so that the
  // estimator counts it as a new view) and wait for the second fused view.
  const geometry_msgs::TransformStamped camera =
      tf_buffer.lookupTransform("world", "camera_optical_frame", ros::Time(0), ros::Duration(5.0));
  const Eigen::Vector3d object_position = Eigen::Vector3d::Zero();  // the camera's object_pose
  const Eigen::Vector3d current(camera.transform.translation.x, camera.transform.translation.y,
                                camera.transform.translation.z);
  const geometry_msgs::Pose* target = nullptr;
  for (const geometry_msgs::Pose& pose : next_best_view.response.ranked.poses) {
    const Eigen::Vector3d position(pose.position.x, pose.position.y, pose.position.z);
    if (angleBetween(position - object_position, current - object_position) > M_PI / 4) {
      target = &pose;
      break;
    }
  }
  ASSERT_NE(target, nullptr) << "no ranked candidate 45 degrees from the current view";
  MoveCamera move;
  move.request.mode = MoveCamera::Request::MODE_POSE;
  move.request.pose = *target;
  ASSERT_TRUE(ros::service::call("simulated_depth_camera/move_to", move));
  ASSERT_TRUE(move.response.success) << move.response.message;
  EXPECT_TRUE(waitForViews(state, 2, 120.0)) << "the view after the move was not fused";

  // Zero copy: every cloud the camera published reached this process as the camera's own
  // object. roscpp keeps one subscription per topic and process, so the estimator's callback got
  // the same object.
  EXPECT_GT(clouds.received.load(), 0);
  EXPECT_EQ(clouds.created.load(), 0)
      << clouds.created << " of " << clouds.received << " clouds were deserialised copies";
}

}  // namespace

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "nodelets_closed_loop");
  return RUN_ALL_TESTS();
}
