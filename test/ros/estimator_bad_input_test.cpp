// rostest: the orientation_estimator survives bad clouds and missing tf. After each kind of bad
// input it must count the cloud as skipped in its diagnostics (the test waits for that, not for a
// guessed time), still be alive (answer ~reset) and publish no estimate for it, and afterwards a
// good rendered mug cloud must still give an estimate.

#include <gtest/gtest.h>
#include <ros/ros.h>
#include <sensor_msgs/point_cloud2_iterator.h>
#include <std_srvs/Trigger.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "estimator_diagnostics_counters.h"
#include "mug_view_publisher.h"
#include "view_direction_classification/common/quaternion.h"

namespace vdc {
namespace {

constexpr const char* kResetService = "orientation_estimator/reset";
// [s] The diagnostics report every second; a skipped cloud shows in the next report (the slowest
// bad cloud, one whose tf never arrives, waits tf_timeout = 0.2 s first).
constexpr double kDiagnosticsTimeout = 10.0;

class EstimatorBadInput : public testing::Test {
 protected:
  EstimatorBadInput()
      : views_(node_, meshPath(), Eigen::Isometry3d::Identity()),
        estimates_(node_, "orientation_estimator/estimate"),
        counters_(node_) {}

  static std::string meshPath() {
    std::string path;
    ros::NodeHandle("~").getParam("mesh", path);
    return path;
  }

  void SetUp() override {
    ASSERT_TRUE(ros::service::waitForService(kResetService, ros::Duration(60.0)));
    ASSERT_TRUE(views_.waitUntilConnected(30.0));
    ASSERT_TRUE(estimates_.waitUntilConnected(30.0));
    ASSERT_TRUE(counters_.current(EstimatorDiagnosticsCounters::kSkipped, 30.0))
        << "the estimator reports no diagnostics counters";
    // A valid camera pose, so clouds in the camera frame fail for their content, not for tf.
    camera_pose_ =
        Eigen::Isometry3d(cameraFromObject(Eigen::Vector3d(1, 0, 0.5), 0.6, 0.0)).inverse();
  }

  // Publishes `cloud` (with the camera tf at its stamp unless it is in another frame), waits until
  // the node's diagnostics count it as skipped, then checks that it fused nothing, still answers
  // ~reset and published no estimate.
  void expectSurvivesWithoutEstimate(sensor_msgs::PointCloud2 cloud, const std::string& what) {
    using Counters = EstimatorDiagnosticsCounters;
    const ros::Time stamp = ros::Time::now();
    cloud.header.stamp = stamp;
    // The node's tf lookup waits tf_timeout for this transform: no sleep needed between the two.
    if (cloud.header.frame_id == kCameraFrame) views_.publishTransform(camera_pose_, stamp);
    const std::size_t before = estimates_.count();
    const auto skipped = counters_.current(Counters::kSkipped, kDiagnosticsTimeout);
    const auto fused = counters_.current(Counters::kFused, kDiagnosticsTimeout);
    ASSERT_TRUE(skipped && fused);
    views_.publisher().publish(cloud);
    EXPECT_TRUE(counters_.waitUntilAbove(Counters::kSkipped, *skipped, kDiagnosticsTimeout))
        << "the diagnostics did not count " << what << " as skipped within " << kDiagnosticsTimeout
        << " s";
    EXPECT_EQ(counters_.current(Counters::kFused, 0.0), fused) << what << " was fused";
    std_srvs::Trigger trigger;
    EXPECT_TRUE(ros::service::call(kResetService, trigger)) << "no ~reset answer after " << what;
    EXPECT_TRUE(trigger.response.success) << what;
    EXPECT_EQ(estimates_.count(), before) << "an estimate was published for " << what;
  }

  static sensor_msgs::PointCloud2 xyzCloud(std::size_t width, std::size_t height,
                                           const std::string& frame) {
    sensor_msgs::PointCloud2 cloud;
    cloud.header.frame_id = frame;
    sensor_msgs::PointCloud2Modifier modifier(cloud);
    modifier.setPointCloud2FieldsByString(1, "xyz");
    modifier.resize(width * height);
    cloud.width = width;
    cloud.height = height;
    cloud.row_step = width * cloud.point_step;
    return cloud;
  }

  static void fillCloud(sensor_msgs::PointCloud2& cloud, float value) {
    for (sensor_msgs::PointCloud2Iterator<float> x(cloud, "x"); x != x.end(); ++x) {
      x[0] = value;
      x[1] = value;
      x[2] = value;
    }
  }

  ros::NodeHandle node_;
  MugViewPublisher views_;
  EstimateRecorder estimates_;
  EstimatorDiagnosticsCounters counters_;
  Eigen::Isometry3d camera_pose_;
};

TEST_F(EstimatorBadInput, SurvivesEmptyCloud) {
  expectSurvivesWithoutEstimate(xyzCloud(0, 0, kCameraFrame), "an empty cloud");
}

TEST_F(EstimatorBadInput, SurvivesAllNaNOrganisedCloud) {
  sensor_msgs::PointCloud2 cloud = xyzCloud(640, 480, kCameraFrame);
  fillCloud(cloud, std::numeric_limits<float>::quiet_NaN());
  expectSurvivesWithoutEstimate(cloud, "an all-NaN cloud");
}

TEST_F(EstimatorBadInput, SurvivesCloudWithoutXyzFields) {
  sensor_msgs::PointCloud2 cloud;
  cloud.header.frame_id = kCameraFrame;
  sensor_msgs::PointCloud2Modifier modifier(cloud);
  modifier.setPointCloud2Fields(1, "intensity", 1, sensor_msgs::PointField::FLOAT32);
  modifier.resize(100);
  expectSurvivesWithoutEstimate(cloud, "a cloud without x, y, z");
}

TEST_F(EstimatorBadInput, SurvivesSinglePoint) {
  sensor_msgs::PointCloud2 cloud = xyzCloud(1, 1, kCameraFrame);
  fillCloud(cloud, 0.5f);
  expectSurvivesWithoutEstimate(cloud, "a one-point cloud");
}

TEST_F(EstimatorBadInput, SurvivesAMillionPoints) {
  sensor_msgs::PointCloud2 cloud = xyzCloud(1000, 1000, kCameraFrame);
  std::mt19937 generator(3);
  std::uniform_real_distribution<float> coordinate(-0.5f, 0.5f);
  for (sensor_msgs::PointCloud2Iterator<float> x(cloud, "x"); x != x.end(); ++x) {
    x[0] = coordinate(generator);
    x[1] = coordinate(generator);
    x[2] = 1.0f + coordinate(generator);
  }
  expectSurvivesWithoutEstimate(cloud, "a million points");
}

TEST_F(EstimatorBadInput, SurvivesUnknownFrame) {
  sensor_msgs::PointCloud2 cloud = xyzCloud(10, 1, "no_such_frame");
  fillCloud(cloud, 0.5f);
  expectSurvivesWithoutEstimate(cloud, "a cloud in an unknown frame");
}

TEST_F(EstimatorBadInput, SurvivesEmptyFrameId) {
  sensor_msgs::PointCloud2 cloud = xyzCloud(10, 1, "");
  fillCloud(cloud, 0.5f);
  expectSurvivesWithoutEstimate(cloud, "a cloud without a frame id");
}

TEST_F(EstimatorBadInput, SurvivesTfThatNeverArrivesForTheStamp) {
  // The camera frame is known, but only at earlier stamps: the lookup waits for the timeout.
  views_.publishTransform(camera_pose_, ros::Time::now() - ros::Duration(5.0),
                          "camera_without_recent_tf");
  sensor_msgs::PointCloud2 cloud = xyzCloud(10, 1, "camera_without_recent_tf");
  fillCloud(cloud, 0.5f);
  expectSurvivesWithoutEstimate(cloud, "a cloud whose tf never arrives");
}

TEST_F(EstimatorBadInput, StillEstimatesFromAGoodCloudAfterBadOnes) {
  sensor_msgs::PointCloud2 empty = xyzCloud(0, 0, kCameraFrame);
  expectSurvivesWithoutEstimate(empty, "an empty cloud");
  const ros::Time stamp = ros::Time::now();
  views_.publishView(Eigen::Vector3d(1, 0, 0.5), 0.6, 0.0, stamp, 1);
  const auto estimate = estimates_.waitFor(stamp, 60.0);
  ASSERT_TRUE(estimate) << "no estimate for a good mug cloud";
  EXPECT_FALSE(estimate->components.empty());
  EXPECT_EQ(estimate->object_id, "mug");
}

TEST_F(EstimatorBadInput, OlderStampResetsTheBeliefBeforeFusing) {
  // View A, then view B, then view A again with a stamp before B's (a looping bag). Without a
  // reset the third belief would fuse three views and be sharper than the second; with the reset
  // it holds one view again, so its entropy is back near the first's. (Not bit-equal: the
  // camera pose at the third stamp may come out of tf interpolated, and a one-view belief's MAP
  // is any point of its girdles.)
  const Eigen::Vector3d a(1, 0, 0.5), b(-0.2, -1.0, -0.6);
  std_srvs::Trigger trigger;
  ASSERT_TRUE(ros::service::call(kResetService, trigger));
  const ros::Time t0 = ros::Time::now();
  views_.publishView(a, 0.6, 0.0, t0, 1);
  const auto first = estimates_.waitFor(t0, 60.0);
  ASSERT_TRUE(first);
  views_.publishView(b, 0.6, 0.5, t0 + ros::Duration(1.0), 2);
  const auto second = estimates_.waitFor(t0 + ros::Duration(1.0), 60.0);
  ASSERT_TRUE(second);
  ASSERT_GT(first->entropy - second->entropy, 0.2) << "the second view should sharpen the belief";
  views_.publishView(a, 0.6, 0.0, t0 + ros::Duration(0.5), 1);
  const auto third = estimates_.waitFor(t0 + ros::Duration(0.5), 60.0);
  ASSERT_TRUE(third);
  EXPECT_GT(third->entropy, second->entropy + 0.8 * (first->entropy - second->entropy));
}

// A soak tells a leak from the allocator keeping freed pages by this count (doc/performance.md).
TEST_F(EstimatorBadInput, TheDiagnosticsReportTheHeapInUseAndWhatTheAllocatorHolds) {
  ASSERT_TRUE(counters_.current(EstimatorDiagnosticsCounters::kReceived, kDiagnosticsTimeout));
  const std::string in_use = counters_.text("heap in use [MiB]");
  const std::string held = counters_.text("heap held [MiB]");
  ASSERT_FALSE(in_use.empty()) << "no heap count on /diagnostics";
  ASSERT_FALSE(held.empty());
  // A node with a model loaded holds megabytes, and the allocator holds what is in use.
  EXPECT_GT(std::stod(in_use), 1.0);
  EXPECT_GE(std::stod(held), std::stod(in_use));
}

TEST_F(EstimatorBadInput, AfterACloudTheNodeGivesItsHeapsFreePagesBack) {
  // Any cloud the worker took: it releases once the cloud is done, and the first cloud after
  // start-up always releases.
  expectSurvivesWithoutEstimate(xyzCloud(0, 0, kCameraFrame), "an empty cloud");
  std::string releases;
  for (ros::WallTime end = ros::WallTime::now() + ros::WallDuration(kDiagnosticsTimeout);
       ros::WallTime::now() < end; ros::WallDuration(0.1).sleep()) {
    releases = counters_.text("heap releases");
    if (!releases.empty() && std::stoi(releases) >= 1) break;
  }
  ASSERT_FALSE(releases.empty()) << "no heap release count on /diagnostics";
  EXPECT_GE(std::stoi(releases), 1);
  const std::string released = counters_.text("heap given back by the last release [MiB]");
  ASSERT_FALSE(released.empty());
  EXPECT_GE(std::stod(released), 0.0);
}

}  // namespace
}  // namespace vdc

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "estimator_bad_input_test");
  ros::AsyncSpinner spinner(1);
  spinner.start();
  return RUN_ALL_TESTS();
}
