#include "view_direction_classification/estimation/object_segmentation.h"

#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

// A 60 x 60 cm table at z = 0 (2 mm grid) with a 6 cm cube of points standing on it around
// (0.1, 0, 0.03), a small box far away in x, and NaN padding.
pcl::PointCloud<pcl::PointXYZ> tableScene() {
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (float x = -0.3f; x <= 0.3f; x += 0.005f) {
    for (float y = -0.3f; y <= 0.3f; y += 0.005f) cloud.push_back(pcl::PointXYZ(x, y, 0.0f));
  }
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> unit(-0.03f, 0.03f);
  for (int i = 0; i < 3000; ++i) {
    cloud.push_back(pcl::PointXYZ(0.1f + unit(rng), unit(rng), 0.035f + unit(rng)));
  }
  for (int i = 0; i < 400; ++i) {
    cloud.push_back(
        pcl::PointXYZ(-0.2f + 0.3f * unit(rng), 0.2f + 0.3f * unit(rng), 0.02f + 0.3f * unit(rng)));
  }
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int i = 0; i < 100; ++i) cloud.push_back(pcl::PointXYZ(nan, nan, nan));
  cloud.width = static_cast<std::uint32_t>(cloud.size());
  cloud.height = 1;
  cloud.is_dense = false;
  return cloud;
}

TEST(ObjectSegmentationTest, NoneKeepsEveryFinitePoint) {
  const pcl::PointCloud<pcl::PointXYZ> scene = tableScene();
  const pcl::PointCloud<pcl::PointXYZ> object = segmentObject(scene, {});
  EXPECT_EQ(object.size(), scene.size() - 100);
  EXPECT_TRUE(object.is_dense);
}

TEST(ObjectSegmentationTest, RegionOfInterestRemovesTheTableAndKeepsTheObject) {
  SegmentationParameters parameters;
  parameters.mode = SegmentationMode::kRegionOfInterest;
  parameters.roi_centre = Eigen::Vector3d(0.1, 0.0, 0.03);
  parameters.roi_radius = 0.12;
  const pcl::PointCloud<pcl::PointXYZ> object = segmentObject(tableScene(), parameters);
  ASSERT_GT(object.size(), 2500u);
  EXPECT_LE(object.size(), 3000u);
  for (const pcl::PointXYZ& p : object.points) {
    EXPECT_GT(p.z, 0.004f);          // no table point
    EXPECT_NEAR(p.x, 0.1f, 0.031f);  // only the cube
  }
}

TEST(ObjectSegmentationTest, NothingInTheRegionGivesAnEmptyCloud) {
  SegmentationParameters parameters;
  parameters.mode = SegmentationMode::kRegionOfInterest;
  parameters.roi_centre = Eigen::Vector3d(5, 5, 5);
  EXPECT_TRUE(segmentObject(tableScene(), parameters).empty());
  EXPECT_TRUE(segmentObject(pcl::PointCloud<pcl::PointXYZ>(), parameters).empty());
}

TEST(ObjectSegmentationTest, RefusesInvalidParameters) {
  SegmentationParameters parameters;
  parameters.cluster_tolerance = 0;
  EXPECT_THROW(checkSegmentationParameters(parameters), Error);
  parameters = {};
  parameters.min_plane_fraction = 1.5;
  EXPECT_THROW(segmentObject(tableScene(), parameters), Error);
  parameters = {};
  parameters.roi_centre.x() = std::numeric_limits<double>::infinity();
  EXPECT_THROW(checkSegmentationParameters(parameters), Error);
}

}  // namespace
}  // namespace vdc
