#include "view_direction_classification/ros/cloud_conversions.h"

#include <gtest/gtest.h>
#include <pcl_conversions/pcl_conversions.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include "view_direction_classification/common/error.h"

namespace vdc {
namespace {

sensor_msgs::PointCloud2 makeOrganisedMsg() {
  pcl::PointCloud<pcl::PointXYZ> cloud(3, 2);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    cloud[i] = pcl::PointXYZ(0.1f * i, -0.2f * i, 0.5f + i);
  }
  cloud[4].x = cloud[4].y = cloud[4].z = std::numeric_limits<float>::quiet_NaN();
  cloud.is_dense = false;
  sensor_msgs::PointCloud2 msg;
  pcl::toROSMsg(cloud, msg);
  msg.header.frame_id = "camera_optical";
  return msg;
}

void expectRefusal(const sensor_msgs::PointCloud2& msg, const std::string& part) {
  try {
    toXyzCloud(msg);
    FAIL() << "accepted a bad cloud; expected an error mentioning '" << part << "'";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find(part), std::string::npos) << error.what();
  }
}

TEST(CloudConversions, KeepsCoordinatesShapeAndNaNPointsOfAnOrganisedCloud) {
  const pcl::PointCloud<pcl::PointXYZ> cloud = toXyzCloud(makeOrganisedMsg());
  ASSERT_EQ(cloud.width, 3u);
  ASSERT_EQ(cloud.height, 2u);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (i == 4) {
      EXPECT_TRUE(std::isnan(cloud[i].x));
      continue;
    }
    EXPECT_EQ(cloud[i].x, 0.1f * i);
    EXPECT_EQ(cloud[i].y, -0.2f * i);
    EXPECT_EQ(cloud[i].z, 0.5f + i);
  }
}

TEST(CloudConversions, ReadsXyzOutOfACloudWithMoreFields) {
  pcl::PointCloud<pcl::PointXYZRGBNormal> rich;
  pcl::PointXYZRGBNormal p;
  p.x = 1.0f;
  p.y = 2.0f;
  p.z = 3.0f;
  p.r = 200;
  rich.push_back(p);
  sensor_msgs::PointCloud2 msg;
  pcl::toROSMsg(rich, msg);
  const pcl::PointCloud<pcl::PointXYZ> cloud = toXyzCloud(msg);
  ASSERT_EQ(cloud.size(), 1u);
  EXPECT_EQ(cloud[0].x, 1.0f);
  EXPECT_EQ(cloud[0].y, 2.0f);
  EXPECT_EQ(cloud[0].z, 3.0f);
}

TEST(CloudConversions, EmptyCloudConvertsToEmptyCloud) {
  sensor_msgs::PointCloud2 msg;
  pcl::toROSMsg(pcl::PointCloud<pcl::PointXYZ>(), msg);
  EXPECT_TRUE(toXyzCloud(msg).empty());
}

// fuzz/cloud_conversion_fuzzer's first find: rows of no points, and no data behind them (PCL
// took the address of a first point and walked every one of 4e9 empty rows).
TEST(CloudConversions, EmptyOrganisedCloudKeepsItsShapeWithoutReadingData) {
  sensor_msgs::PointCloud2 msg = makeOrganisedMsg();
  msg.header.stamp.fromNSec(1234567000);
  msg.width = 0;
  msg.height = 0xffffffffu;
  msg.row_step = 0;
  msg.data.clear();
  const pcl::PointCloud<pcl::PointXYZ> cloud = toXyzCloud(msg);
  EXPECT_TRUE(cloud.empty());
  EXPECT_EQ(cloud.width, 0u);
  EXPECT_EQ(cloud.height, 0xffffffffu);
  EXPECT_EQ(cloud.header.frame_id, "camera_optical");
  EXPECT_EQ(cloud.header.stamp, 1234567u);  // PCL stamps are microseconds
}

// fuzz/cloud_conversion_fuzzer's second find: the bytes were read as little-endian.
TEST(CloudConversions, ReadsABigEndianCloudInItsByteOrder) {
  const sensor_msgs::PointCloud2 little = makeOrganisedMsg();
  sensor_msgs::PointCloud2 big = little;
  big.is_bigendian = true;
  for (std::size_t point = 0; point < big.data.size(); point += big.point_step) {
    for (const auto& field : big.fields) {
      if (field.name != "x" && field.name != "y" && field.name != "z") continue;
      std::reverse(big.data.begin() + point + field.offset,
                   big.data.begin() + point + field.offset + sizeof(float));
    }
  }
  const pcl::PointCloud<pcl::PointXYZ> expected = toXyzCloud(little), cloud = toXyzCloud(big);
  ASSERT_EQ(cloud.size(), expected.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (i == 4) continue;  // NaN
    EXPECT_EQ(cloud[i].x, expected[i].x);
    EXPECT_EQ(cloud[i].y, expected[i].y);
    EXPECT_EQ(cloud[i].z, expected[i].z);
  }
}

// Its third: PCL 1.13's fromROSMsg merged x at 4 and z at 12 into one copy over y at 0.
TEST(CloudConversions, ReadsFieldsInAnyOrderAndWithGaps) {
  sensor_msgs::PointCloud2 msg;
  msg.fields.resize(3);
  const char* names[] = {"y", "x", "z"};
  const std::uint32_t offsets[] = {0, 4, 12};
  for (int k = 0; k < 3; ++k) {
    msg.fields[k].name = names[k];
    msg.fields[k].offset = offsets[k];
    msg.fields[k].datatype = sensor_msgs::PointField::FLOAT32;
    msg.fields[k].count = 1;
  }
  msg.width = 2;
  msg.height = 1;
  msg.point_step = 16;
  msg.row_step = 32;
  const float values[2][4] = {{2.0f, 1.0f, 99.0f, 3.0f}, {-2.0f, -1.0f, 99.0f, -3.0f}};
  msg.data.resize(sizeof(values));
  std::memcpy(msg.data.data(), values, sizeof(values));
  const pcl::PointCloud<pcl::PointXYZ> cloud = toXyzCloud(msg);
  ASSERT_EQ(cloud.size(), 2u);
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(cloud[i].x, values[i][1]);
    EXPECT_EQ(cloud[i].y, values[i][0]);
    EXPECT_EQ(cloud[i].z, values[i][3]);
  }
}

TEST(CloudConversions, RefusesCloudWithoutZNamingTheMissingField) {
  sensor_msgs::PointCloud2 msg = makeOrganisedMsg();
  for (auto& field : msg.fields) {
    if (field.name == "z") field.name = "intensity";
  }
  expectRefusal(msg, "no field 'z'");
}

TEST(CloudConversions, RefusesCloudWithNoFieldsAtAll) {
  sensor_msgs::PointCloud2 msg = makeOrganisedMsg();
  msg.fields.clear();
  expectRefusal(msg, "no field 'x' (its fields: none)");
}

TEST(CloudConversions, RefusesDoublePrecisionCoordinates) {
  sensor_msgs::PointCloud2 msg = makeOrganisedMsg();
  msg.fields[1].datatype = sensor_msgs::PointField::FLOAT64;
  expectRefusal(msg, "field 'y' of datatype 8");
}

TEST(CloudConversions, RefusesFieldBeyondThePointStep) {
  sensor_msgs::PointCloud2 msg = makeOrganisedMsg();
  msg.fields[0].offset = msg.point_step;
  expectRefusal(msg, "beyond its point_step");
}

TEST(CloudConversions, RefusesDataShorterThanItsHeaderClaims) {
  sensor_msgs::PointCloud2 msg = makeOrganisedMsg();
  msg.data.resize(msg.data.size() - 1);
  expectRefusal(msg, "inconsistent");
}

}  // namespace
}  // namespace vdc
