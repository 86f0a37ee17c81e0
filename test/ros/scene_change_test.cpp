// rostest (scene_change.test): the orientation_estimator with segmentation `scene` and the one
// ~model, on a rendered table. The mug is found, then taken away: after one view of its empty
// place it is still PRESENT, after the second (absent_views 2) ~instances lists it GONE with its
// gone_since, and its tf frame is no longer sent.

#include <gtest/gtest.h>
#include <ros/ros.h>
#include <std_srvs/Trigger.h>
#include <tf2_msgs/TFMessage.h>
#include <view_direction_classification/ObjectInstances.h>

#include <mutex>
#include <optional>
#include <random>
#include <set>
#include <string>

#include "mug_view_publisher.h"
#include "view_direction_classification/geometry/primitive_meshes.h"
#include "view_direction_classification/geometry/scene.h"

namespace vdc {
namespace {

using view_direction_classification::ObjectInstance;
using view_direction_classification::ObjectInstances;

constexpr const char* kResetService = "orientation_estimator/reset";
constexpr const char* kMug = "mug_1";  // the config's object_id, the first instance

// The latest ~instances and the child frames of every /tf message since the last clear().
class SceneRecorder {
 public:
  explicit SceneRecorder(ros::NodeHandle& node)
      : instances_(node.subscribe("orientation_estimator/instances", 10,
                                  &SceneRecorder::onInstances, this)),
        tf_(node.subscribe("/tf", 100, &SceneRecorder::onTf, this)) {}

  std::optional<ObjectInstances> waitFor(const ros::Time& stamp, double timeout) {
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(timeout);
    while (ros::ok() && ros::WallTime::now() < deadline) {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        if (latest_ && latest_->header.stamp == stamp) return latest_;
      }
      ros::WallDuration(0.02).sleep();
    }
    return std::nullopt;
  }

  void clearFrames() {
    std::lock_guard<std::mutex> lock(mutex_);
    frames_.clear();
  }
  std::set<std::string> frames() {
    std::lock_guard<std::mutex> lock(mutex_);
    return frames_;
  }

 private:
  void onInstances(const ObjectInstances& message) {
    std::lock_guard<std::mutex> lock(mutex_);
    latest_ = message;
  }
  void onTf(const tf2_msgs::TFMessage& message) {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& transform : message.transforms) frames_.insert(transform.child_frame_id);
  }

  std::mutex mutex_;
  std::optional<ObjectInstances> latest_;
  std::set<std::string> frames_;
  ros::Subscriber instances_, tf_;
};

// A table with a 25 cm cylinder (too large for the mug; the table is centred under it) and,
// when `with_mug`, the mug at the fixed frame's origin.
TriangleMesh tableScene(const TriangleMesh& mug, bool with_mug) {
  const double table_top = -0.0475;  // the mug's bottom, 9.5 / 2 cm below its origin
  Scene scene;
  scene.object.mesh = makeCylinderMesh(0.03, 0.25);
  scene.object.world_from_part.translation() = Eigen::Vector3d(-0.25, 0.05, table_top);
  scene.table_size = Eigen::Vector2d(1.4, 1.0);
  if (with_mug) scene.distractors.push_back({mug, Eigen::Isometry3d::Identity()});
  return sceneMesh(scene);
}

class SceneChange : public testing::Test {
 protected:
  SceneChange()
      : mug_(loadMesh(meshPath())),
        views_(node_, meshPath(), Eigen::Isometry3d::Identity()),
        recorder_(node_) {}

  static std::string meshPath() {
    std::string path;
    ros::NodeHandle("~").getParam("mesh", path);
    return path;
  }

  void SetUp() override {
    ASSERT_TRUE(ros::service::waitForService(kResetService, ros::Duration(60.0)));
    ASSERT_TRUE(views_.waitUntilConnected(30.0));
  }

  // Publishes the camera's tf and the cloud of the table (with or without the mug) seen from
  // `direction` at 0.7 m, stamped `stamp`, and returns the ~instances of that stamp.
  std::optional<ObjectInstances> look(bool with_mug, const Eigen::Vector3d& direction,
                                      const ros::Time& stamp) {
    const DepthRenderer renderer(tableScene(mug_, with_mug));
    const Eigen::Isometry3d camera_from_world = cameraFromObject(direction.normalized(), 0.7, 0.0);
    std::mt19937 rng(static_cast<unsigned>(stamp.sec));
    const pcl::PointCloud<pcl::PointXYZ> cloud =
        renderer.render(camera_from_world, DepthNoiseModel{true}, &rng);
    views_.publishTransform(camera_from_world.inverse(), stamp);
    ros::WallDuration(0.05).sleep();  // the tf before the cloud
    sensor_msgs::PointCloud2 message;
    pcl::toROSMsg(cloud, message);
    message.header.frame_id = kCameraFrame;
    message.header.stamp = stamp;
    views_.publisher().publish(message);
    return recorder_.waitFor(stamp, 60.0);
  }

  TriangleMesh mug_;
  ros::NodeHandle node_;
  MugViewPublisher views_;
  SceneRecorder recorder_;
};

const ObjectInstance* named(const ObjectInstances& message, const std::string& name) {
  for (const ObjectInstance& instance : message.instances) {
    if (instance.name == name) return &instance;
  }
  return nullptr;
}

TEST_F(SceneChange, AMugTakenAwayIsListedGoneAfterTwoViewsAndLosesItsTfFrame) {
  const ros::Time start = ros::Time::now();
  auto instances = look(true, Eigen::Vector3d(1.0, 0.2, 0.9), start);
  ASSERT_TRUE(instances) << "no ~instances for the first frame";
  const ObjectInstance* mug = named(*instances, kMug);
  ASSERT_NE(mug, nullptr) << "the mug was not found";
  EXPECT_EQ(mug->state, ObjectInstance::PRESENT);
  const std::uint32_t id = mug->id;
  recorder_.clearFrames();
  ros::WallDuration(0.5).sleep();
  EXPECT_EQ(recorder_.frames().count(kMug), 1u) << "the mug's tf frame is not sent";

  instances = look(false, Eigen::Vector3d(0.6, 0.8, 0.9), start + ros::Duration(1.0));
  ASSERT_TRUE(instances);
  mug = named(*instances, kMug);
  ASSERT_NE(mug, nullptr) << "one view of its empty place removed it";
  EXPECT_EQ(mug->state, ObjectInstance::PRESENT) << "gone after one view";

  const ros::Time gone_at = start + ros::Duration(2.0);
  instances = look(false, Eigen::Vector3d(-0.2, 1.0, 0.8), gone_at);
  ASSERT_TRUE(instances);
  mug = named(*instances, kMug);
  ASSERT_NE(mug, nullptr) << "a gone instance is listed";
  EXPECT_EQ(mug->id, id);
  EXPECT_EQ(mug->state, ObjectInstance::GONE);
  // The stamp went through a double [s]: equal to the microsecond.
  EXPECT_NEAR((mug->gone_since - gone_at).toSec(), 0.0, 1e-6);

  // The node re-sends its frames at tf_rate (10 Hz): a second without mug_1.
  recorder_.clearFrames();
  ros::WallDuration(1.0).sleep();
  EXPECT_EQ(recorder_.frames().count(kMug), 0u) << "the gone mug's tf frame is still sent";
}

}  // namespace
}  // namespace vdc

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "scene_change_test");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  return RUN_ALL_TESTS();
}
