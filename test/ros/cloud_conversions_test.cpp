#include "view_direction_classification/ros/cloud_conversions.h"

#include <gtest/gtest.h>
#include <pcl_conversions/pcl_conversions.h>

#include <cmath>
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
