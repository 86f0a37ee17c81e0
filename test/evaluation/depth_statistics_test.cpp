#include "view_direction_classification/evaluation/depth_statistics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "support/geometry_test_meshes.h"
#include "view_direction_classification/geometry/depth_renderer.h"

namespace vdc {
namespace {

using Cloud = pcl::PointCloud<pcl::PointXYZ>;

Cloud render(const TriangleMesh& mesh, const Eigen::Isometry3d& pose, const SensorModel& sensor,
             bool noise = true) {
  std::mt19937 rng(4);
  return DepthRenderer(mesh).render(pose, DepthNoiseModel{noise, sensor}, &rng);
}

// A 0.8 m square at about 1 m tilted 40 degrees: depths from 0.75 to 1.25 m.
Cloud tiltedPlane(const SensorModel& sensor) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitY()).toRotationMatrix();
  pose.translation() = Eigen::Vector3d(0.0, 0.0, 1.0);
  return render(test::makeSquare(0.6f, 0.0f), pose, sensor);
}

TEST(DepthStatistics, QuantisedDisparityShowsTheKinectStepAndFewLevels) {
  const DepthStatistics sl =
      depthStatistics(tiltedPlane(sensorModel(DepthSensor::kStructuredLight)));
  const DepthStatistics gaussian = depthStatistics(tiltedPlane(SensorModel{}));
  EXPECT_NEAR(sl.median_depth, 1.0, 0.1);  // more pixels on the near half
  // 1/8 px on the Kinect's grid; at 1 m a step of 2.9 mm, 3.5 levels per cm.
  EXPECT_NEAR(sl.disparity_step_px, 0.125, 1e-3);
  EXPECT_LT(sl.levels_per_cm, 5.0);
  EXPECT_LT(gaussian.disparity_step_px, 0.01);
  EXPECT_GT(gaussian.levels_per_cm, 100.0);
}

TEST(DepthStatistics, EdgeFiguresSeeMissingPixelsAndFlyingPixelsAtDepthEdgesOnly) {
  const Eigen::Isometry3d camera = Eigen::Isometry3d::Identity();
  const DepthStatistics exact = depthStatistics(render(test::makeDepthStep(), camera, {}, false));
  SensorModel dropouts;
  dropouts.kind = DepthSensor::kStructuredLight;
  dropouts.edge_dropout = 1.0;
  const DepthStatistics lost = depthStatistics(render(test::makeDepthStep(), camera, dropouts));
  const DepthStatistics tof = depthStatistics(
      render(test::makeDepthStep(), camera, sensorModel(DepthSensor::kTimeOfFlight)));
  // Two edges per row through the foreground (132 rows).
  EXPECT_EQ(exact.depth_edges, 2u * 132u);
  EXPECT_EQ(exact.edge_gap_fraction, 0.0);
  EXPECT_EQ(exact.flat_gap_fraction, 0.0);
  EXPECT_EQ(exact.flying_fraction, 0.0);
  EXPECT_EQ(lost.edge_gap_fraction, 1.0);
  EXPECT_EQ(lost.flat_gap_fraction, 0.0);
  EXPECT_GT(tof.flying_fraction, 0.1);
  EXPECT_LT(tof.edge_gap_fraction, 0.01);
}

TEST(DepthStatistics, AnUnorganisedCloudHasNoEdgeFiguresAndAnEmptyOneNoFigures) {
  Cloud cloud = tiltedPlane(SensorModel{});
  cloud.width = static_cast<std::uint32_t>(cloud.size());
  cloud.height = 1;
  const DepthStatistics unorganised = depthStatistics(cloud);
  EXPECT_GT(unorganised.points, 10000u);
  EXPECT_TRUE(std::isnan(unorganised.edge_gap_fraction));
  EXPECT_TRUE(std::isnan(unorganised.flying_fraction));
  const DepthStatistics empty = depthStatistics(Cloud());
  EXPECT_EQ(empty.points, 0u);
  EXPECT_TRUE(std::isnan(empty.median_depth));
}

}  // namespace
}  // namespace vdc
