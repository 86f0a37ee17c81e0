// rostest: rendered mug clouds from random directions, with a moving camera tf, played into the
// orientation_estimator; its MAP orientation must converge to the mug's true orientation.

#include <gtest/gtest.h>
#include <ros/ros.h>
#include <std_srvs/Trigger.h>
#include <tf2/exceptions.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>

#include <cmath>
#include <random>
#include <string>

#include "mug_view_publisher.h"
#include "view_direction_classification/common/quaternion.h"
#include "view_direction_classification/common/rotation_error.h"

namespace vdc {
namespace {

// The quick test model has only 12 training directions (about 63 degrees apart), so it cannot
// pin the orientation down to a few degrees. Measured on this sequence (deterministic: fixed
// directions, rolls and noise seeds; config/estimator.yaml with tabletop segmentation, views near
// fused ones tempered): MAP error 27, 28, 30, 31, 32, 31, 30, 23 degrees after views 1..8,
// entropy 2.75 -> 0.31 nats (before frame selection and tempering: 63, 83, 29, 24, 29, 34, 45,
// 39 degrees, 2.44 -> -0.27 nats). The bound, 60 degrees after 8 views, leaves margin and is
// still far below the 126 degrees a random guess averages.
constexpr int kViews = 8;
constexpr double kBoundDeg = 60.0;
// The belief must also have sharpened: at least this many nats below the first view's entropy
// (measured 2.4).
constexpr double kMinEntropyDrop = 1.5;

std::string meshPath() {
  std::string path;
  ros::NodeHandle("~").getParam("mesh", path);
  return path;
}

TEST(EstimatorConvergence,
     MapErrorIsUnder60DegreesAndEntropyDrops1p5NatsAfter8RandomViewsOfTheMug) {
  ros::NodeHandle node;
  const std::string mesh = meshPath();
  ASSERT_FALSE(mesh.empty()) << "the test needs the private parameter ~mesh";
  // The mug stands somewhere in the world, turned, so that neither the fixed frame's identity
  // nor its origin is the answer.
  const Eigen::Vector4d q_true = quaternionFromAxisAngle(Eigen::Vector3d(1.0, 2.0, 3.0), 0.8);
  Eigen::Isometry3d world_from_object = Eigen::Isometry3d::Identity();
  world_from_object.linear() = quaternionToRotationMatrix(q_true);
  world_from_object.translation() = Eigen::Vector3d(0.3, -0.1, 0.05);

  MugViewPublisher views(node, mesh, world_from_object);
  EstimateRecorder estimates(node, "orientation_estimator/estimate");
  ASSERT_TRUE(views.waitUntilConnected(30.0)) << "the estimator never subscribed";
  ASSERT_TRUE(estimates.waitUntilConnected(30.0)) << "the estimator never published";

  std::mt19937 generator(5);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> roll(-M_PI, M_PI);
  double error = 180.0, first_entropy = 0.0, entropy = 0.0;
  for (int view = 0; view < kViews; ++view) {
    const Eigen::Vector3d direction(normal(generator), normal(generator), normal(generator));
    const ros::Time stamp = ros::Time::now();
    views.publishView(direction, 0.6, roll(generator), stamp, 100 + view);
    const auto estimate = estimates.waitFor(stamp, 60.0);
    ASSERT_TRUE(estimate) << "no estimate for view " << view;
    const auto& q = estimate->map_orientation;
    error = rotationErrorDeg(Eigen::Vector4d(q.w, q.x, q.y, q.z), q_true);
    ROS_INFO("view %d: MAP error %.1f deg, %zu components, entropy %.2f", view + 1, error,
             estimate->components.size(), estimate->entropy);
    EXPECT_EQ(estimate->header.frame_id, kFixedFrame);
    entropy = estimate->entropy;
    if (view == 0) first_entropy = entropy;
  }
  EXPECT_LT(error, kBoundDeg);
  EXPECT_LT(entropy, first_entropy - kMinEntropyDrop);
}

// /tf is not latched: a listener that starts after an estimate knows the object frame only
// because the estimator re-sends it at ~tf_rate (10 Hz in config/estimator.yaml), with fresh
// stamps; after ~reset it must stop.
TEST(EstimatorConvergence, ObjectFrameReachesAListenerStartedAfterTheEstimateUntilReset) {
  ros::NodeHandle node;
  const std::string mesh = meshPath();
  ASSERT_FALSE(mesh.empty()) << "the test needs the private parameter ~mesh";
  Eigen::Isometry3d world_from_object = Eigen::Isometry3d::Identity();
  world_from_object.translation() = Eigen::Vector3d(0.2, 0.1, 0.0);
  MugViewPublisher views(node, mesh, world_from_object);
  EstimateRecorder estimates(node, "orientation_estimator/estimate");
  ASSERT_TRUE(views.waitUntilConnected(30.0)) << "the estimator never subscribed";
  ASSERT_TRUE(estimates.waitUntilConnected(30.0)) << "the estimator never published";
  // A new scene (the mug elsewhere): the estimator tracking the previous test's mug would see
  // nothing where it stood (the rendered clouds hold the mug only) and skip the view.
  std_srvs::Trigger start_afresh;
  ASSERT_TRUE(ros::service::call("orientation_estimator/reset", start_afresh));

  const ros::Time stamp = ros::Time::now();
  views.publishView(Eigen::Vector3d(1.0, 0.5, 0.3), 0.6, 0.2, stamp, 7);
  const auto estimate = estimates.waitFor(stamp, 60.0);
  ASSERT_TRUE(estimate) << "no estimate for the view";
  ros::WallDuration(0.5).sleep();  // the one-off broadcast is over before the listener starts

  {
    tf2_ros::Buffer late_buffer;
    tf2_ros::TransformListener late_listener(late_buffer, node);
    geometry_msgs::TransformStamped transform;
    try {
      transform =
          late_buffer.lookupTransform(kFixedFrame, "object", ros::Time(0), ros::Duration(5.0));
    } catch (const tf2::TransformException& error) {
      FAIL() << "a listener started after the estimate never learnt the object frame: "
             << error.what();
    }
    EXPECT_GT(transform.header.stamp, stamp) << "not re-sent with a fresh stamp";
    // The re-sent pose is the estimate's: the same MAP orientation (up to the quaternion sign).
    const auto& q = estimate->map_orientation;
    const auto& r = transform.transform.rotation;
    EXPECT_NEAR(std::abs(q.w * r.w + q.x * r.x + q.y * r.y + q.z * r.z), 1.0, 1e-6);
  }

  std_srvs::Trigger trigger;
  ASSERT_TRUE(ros::service::call("orientation_estimator/reset", trigger));
  ros::WallDuration(0.5).sleep();  // a re-broadcast already in flight arrives before the listener
  tf2_ros::Buffer buffer_after_reset;
  tf2_ros::TransformListener listener_after_reset(buffer_after_reset, node);
  // Ten re-broadcast periods.
  EXPECT_FALSE(
      buffer_after_reset.canTransform(kFixedFrame, "object", ros::Time(0), ros::Duration(1.0)))
      << "the object frame is still broadcast after ~reset";
}

}  // namespace
}  // namespace vdc

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "estimator_convergence_test");
  ros::AsyncSpinner spinner(1);
  spinner.start();
  return RUN_ALL_TESTS();
}
