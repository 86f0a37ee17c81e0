// rostest (scene_labels.test): the orientation_estimator with segmentation `labels` and the one
// ~model. A label image of the wrong size, of another encoding, truncated, or none with the
// cloud's stamp: the cloud is skipped with the reason in the diagnostics, and the node keeps
// serving (~reset answers). A rendered mug with its detector mask of the mapped class: the node
// finds the mug.

#include <gtest/gtest.h>
#include <ros/ros.h>
#include <sensor_msgs/Image.h>
#include <std_srvs/Trigger.h>
#include <view_direction_classification/ObjectInstances.h>

#include <cmath>
#include <mutex>
#include <random>
#include <string>

#include "estimator_diagnostics_counters.h"
#include "mug_view_publisher.h"

namespace vdc {
namespace {

constexpr const char* kResetService = "orientation_estimator/reset";
constexpr const char* kSegmented = "clouds segmented";
constexpr const char* kSkipReason = "last skip reason";
// [s] The diagnostics report every second.
constexpr double kDiagnosticsTimeout = 10.0;
// The mask's label: instance 1 of class 7 (label_class_divisor 1000), which scene_labels.test
// maps to the model.
constexpr std::uint32_t kMugLabel = 7001;

// Collects ~instances (spun by the test's AsyncSpinner).
class InstancesRecorder {
 public:
  explicit InstancesRecorder(ros::NodeHandle& node)
      : subscriber_(node.subscribe("orientation_estimator/instances", 10,
                                   &InstancesRecorder::callback, this)) {}

  // The ~instances message of this stamp, waiting up to `timeout` [s] for it.
  std::optional<view_direction_classification::ObjectInstances> waitFor(const ros::Time& stamp,
                                                                        double timeout) {
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

 private:
  void callback(const view_direction_classification::ObjectInstances& message) {
    std::lock_guard<std::mutex> lock(mutex_);
    latest_ = message;
  }

  std::mutex mutex_;
  std::optional<view_direction_classification::ObjectInstances> latest_;
  ros::Subscriber subscriber_;
};

class SceneLabels : public testing::Test {
 protected:
  SceneLabels()
      : renderer_(loadMesh(meshPath())),
        views_(node_, meshPath(), Eigen::Isometry3d::Identity()),
        labels_publisher_(node_.advertise<sensor_msgs::Image>("labels", 10)),
        instances_(node_),
        counters_(node_, "scene estimate") {}

  static std::string meshPath() {
    std::string path;
    ros::NodeHandle("~").getParam("mesh", path);
    return path;
  }

  void SetUp() override {
    ASSERT_TRUE(ros::service::waitForService(kResetService, ros::Duration(60.0)));
    ASSERT_TRUE(views_.waitUntilConnected(30.0));
    ASSERT_TRUE(waitForSubscriber(labels_publisher_, 30.0)) << "the node does not subscribe labels";
    ASSERT_TRUE(counters_.current(EstimatorDiagnosticsCounters::kSkipped, 30.0))
        << "the node reports no diagnostics counters";
    const Eigen::Isometry3d camera_from_object =
        cameraFromObject(Eigen::Vector3d(1, 0, 0.5), 0.6, 0.0);
    camera_pose_ = camera_from_object.inverse();
    std::mt19937 rng(5);
    cloud_ = renderer_.render(camera_from_object, DepthNoiseModel{true}, &rng);
  }

  // The detector's mask of the rendered mug: every pixel with depth.
  sensor_msgs::Image mugMask(const ros::Time& stamp) const {
    sensor_msgs::Image image;
    image.header.stamp = stamp;
    image.header.frame_id = kCameraFrame;
    image.width = cloud_.width;
    image.height = cloud_.height;
    image.encoding = "mono16";
    image.step = image.width * 2;
    image.data.assign(std::size_t(image.step) * image.height, 0);
    for (std::size_t i = 0; i < cloud_.size(); ++i) {
      if (!std::isfinite(cloud_[i].z)) continue;
      image.data[2 * i] = kMugLabel & 0xFF;  // little-endian
      image.data[2 * i + 1] = kMugLabel >> 8;
    }
    return image;
  }

  // Publishes the label image (unless null), then the camera tf and the cloud with `stamp`.
  void publishFrame(const sensor_msgs::Image* labels, const ros::Time& stamp) {
    if (labels != nullptr) labels_publisher_.publish(*labels);
    views_.publishTransform(camera_pose_, stamp);
    ros::WallDuration(0.05).sleep();  // the label image and tf before the cloud
    sensor_msgs::PointCloud2 cloud;
    pcl::toROSMsg(cloud_, cloud);
    cloud.header.frame_id = kCameraFrame;
    cloud.header.stamp = stamp;
    views_.publisher().publish(cloud);
  }

  // Publishes a frame whose label image is `labels` (or none) and expects it skipped with a
  // reason containing `reason`, the node still answering ~reset.
  void expectSkipped(const sensor_msgs::Image* labels, const ros::Time& stamp,
                     const std::string& reason, const std::string& what) {
    using Counters = EstimatorDiagnosticsCounters;
    const auto skipped = counters_.current(Counters::kSkipped, kDiagnosticsTimeout);
    const auto segmented = counters_.current(kSegmented, kDiagnosticsTimeout);
    ASSERT_TRUE(skipped && segmented);
    publishFrame(labels, stamp);
    EXPECT_TRUE(counters_.waitUntilAbove(Counters::kSkipped, *skipped, kDiagnosticsTimeout))
        << what << " was not counted as skipped";
    EXPECT_NE(counters_.text(kSkipReason).find(reason), std::string::npos)
        << what << ": the skip reason is '" << counters_.text(kSkipReason) << "'";
    EXPECT_EQ(counters_.current(kSegmented, 0.0), segmented) << what << " was segmented";
    std_srvs::Trigger trigger;
    EXPECT_TRUE(ros::service::call(kResetService, trigger)) << "no ~reset answer after " << what;
  }

  DepthRenderer renderer_;
  ros::NodeHandle node_;
  MugViewPublisher views_;
  ros::Publisher labels_publisher_;
  InstancesRecorder instances_;
  EstimatorDiagnosticsCounters counters_;
  Eigen::Isometry3d camera_pose_;
  pcl::PointCloud<pcl::PointXYZ> cloud_;
};

TEST_F(SceneLabels, ACloudWithoutALabelImageOfItsStampIsSkipped) {
  const ros::Time stamp = ros::Time::now();
  const sensor_msgs::Image later = mugMask(stamp + ros::Duration(1.0));
  expectSkipped(&later, stamp, "no label image within labels_stamp_tolerance",
                "a label image of another stamp");
}

TEST_F(SceneLabels, ALabelImageOfAnotherSizeIsSkipped) {
  const ros::Time stamp = ros::Time::now();
  sensor_msgs::Image half;
  half.header.stamp = stamp;
  half.width = cloud_.width / 2;
  half.height = cloud_.height / 2;
  half.encoding = "mono8";
  half.step = half.width;
  half.data.assign(std::size_t(half.step) * half.height, 1);
  expectSkipped(&half, stamp, "they must be pixel-aligned", "a label image of half the size");
}

TEST_F(SceneLabels, ALabelImageOfAnotherEncodingIsSkipped) {
  const ros::Time stamp = ros::Time::now();
  sensor_msgs::Image colour = mugMask(stamp);
  colour.encoding = "rgb8";
  expectSkipped(&colour, stamp, "encoding is 'rgb8'", "an rgb8 image");
}

TEST_F(SceneLabels, ATruncatedLabelImageIsSkipped) {
  const ros::Time stamp = ros::Time::now();
  sensor_msgs::Image truncated = mugMask(stamp);
  truncated.data.resize(truncated.data.size() / 2);
  expectSkipped(&truncated, stamp, "inconsistent", "a truncated label image");
}

// Last (gtest keeps the declaration order): the bad frames above must not have been the first
// segmented one.
TEST_F(SceneLabels, TheMugIsFoundFromItsMask) {
  const auto segmented = counters_.current(kSegmented, kDiagnosticsTimeout);
  ASSERT_TRUE(segmented);
  const ros::Time stamp = ros::Time::now();
  const sensor_msgs::Image mask = mugMask(stamp);
  publishFrame(&mask, stamp);
  const auto instances = instances_.waitFor(stamp, 60.0);
  ASSERT_TRUE(instances) << "no ~instances for the masked frame; last skip reason '"
                         << counters_.text(kSkipReason) << "'";
  ASSERT_EQ(instances->instances.size(), 1u);
  EXPECT_EQ(instances->instances[0].model, "mug");
  EXPECT_EQ(instances->instances[0].name, "mug_1");
  const auto& position = instances->instances[0].pose.pose.position;
  EXPECT_LT(std::hypot(position.x, position.y, position.z), 0.03)
      << "the mug stands at the fixed frame's origin";
}

}  // namespace
}  // namespace vdc

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "scene_labels_test");
  ros::AsyncSpinner spinner(2);
  spinner.start();
  return RUN_ALL_TESTS();
}
