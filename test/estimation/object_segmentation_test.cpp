#include "view_direction_classification/estimation/object_segmentation.h"

#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <utility>

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
  const ObjectSegment object = segmentObject(scene, {});
  EXPECT_EQ(object.points.size(), scene.size() - 100);
  EXPECT_TRUE(object.points.is_dense);
  ASSERT_EQ(object.indices.size(), object.points.size());
  EXPECT_EQ(object.indices.back(), static_cast<int>(scene.size()) - 101);  // the NaNs come last
  EXPECT_TRUE(object.failure.empty());
}

TEST(ObjectSegmentationTest, RegionOfInterestRemovesTheTableAndKeepsTheObject) {
  SegmentationParameters parameters;
  parameters.mode = SegmentationMode::kRegionOfInterest;
  parameters.roi_centre = Eigen::Vector3d(0.1, 0.0, 0.03);
  parameters.roi_radius = 0.12;
  const ObjectSegment object = segmentObject(tableScene(), parameters);
  ASSERT_GT(object.points.size(), 2500u);
  EXPECT_LE(object.points.size(), 3000u);
  ASSERT_TRUE(object.table.has_value());
  EXPECT_NEAR(std::abs((*object.table)(2)), 1.0, 1e-3);  // the table z = 0
  for (const pcl::PointXYZ& p : object.points.points) {
    EXPECT_GT(p.z, 0.004f);          // no table point
    EXPECT_NEAR(p.x, 0.1f, 0.031f);  // only the cube
  }
}

TEST(ObjectSegmentationTest, NothingInTheRegionGivesAnEmptyCloud) {
  SegmentationParameters parameters;
  parameters.mode = SegmentationMode::kRegionOfInterest;
  parameters.roi_centre = Eigen::Vector3d(5, 5, 5);
  EXPECT_TRUE(segmentObject(tableScene(), parameters).points.empty());
  EXPECT_TRUE(segmentObject(pcl::PointCloud<pcl::PointXYZ>(), parameters).points.empty());
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
  parameters = {};
  parameters.extent_tolerance = 1.0;
  EXPECT_THROW(checkSegmentationParameters(parameters), Error);
  parameters = {};
  parameters.border_margin = -1;
  EXPECT_THROW(checkSegmentationParameters(parameters), Error);
  parameters = {};
  parameters.mode = SegmentationMode::kTabletop;  // without the model's extent
  EXPECT_THROW(segmentObject(tableScene(), parameters), Error);
}

TEST(ObjectSegmentationTest, AnObjectTouchingTheBorderOfAnOrganisedCloudIsCutOff) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  pcl::PointCloud<pcl::PointXYZ> image(40, 30, pcl::PointXYZ(nan, nan, nan));
  for (int row = 10; row < 20; ++row) {
    for (int column = 10; column < 20; ++column) image.at(column, row) = pcl::PointXYZ(0, 0, 1);
  }
  EXPECT_TRUE(segmentObject(image, {}).failure.empty());
  image.at(1, 15) = pcl::PointXYZ(0, 0, 1);  // within the 2-pixel margin of the left edge
  EXPECT_NE(segmentObject(image, {}).failure.find("image border"), std::string::npos);
  SegmentationParameters no_margin;
  no_margin.border_margin = 0;
  EXPECT_TRUE(segmentObject(image, no_margin).failure.empty());
}

TEST(ObjectSegmentationTest, ModeNamesRoundTripAndUnknownOnesAreRefused) {
  for (const SegmentationMode mode : {SegmentationMode::kNone, SegmentationMode::kRegionOfInterest,
                                      SegmentationMode::kTabletop}) {
    EXPECT_EQ(parseSegmentationMode(segmentationModeName(mode)), mode);
  }
  EXPECT_THROW(parseSegmentationMode("table"), Error);
}

}  // namespace
}  // namespace vdc

namespace vdc {
namespace {

// `scene` and `labels` name the scene layer (recognition/scene_estimator.h): parsed, but one
// object's segmentation refuses them rather than guess what they mean.
TEST(SceneSegmentationMode, IsParsedButOneObjectsSegmentationRefusesIt) {
  for (const auto& [name, mode] : {std::pair{"scene", SegmentationMode::kScene},
                                   std::pair{"labels", SegmentationMode::kLabels}}) {
    EXPECT_EQ(parseSegmentationMode(name), mode);
    EXPECT_EQ(segmentationModeName(mode), name);
    SegmentationParameters parameters;
    parameters.mode = mode;
    pcl::PointCloud<pcl::PointXYZ> cloud;
    cloud.push_back(pcl::PointXYZ(0.0f, 0.0f, 1.0f));
    EXPECT_THROW(segmentObject(cloud, parameters), Error) << name;
  }
}

}  // namespace
}  // namespace vdc
