// ~memory_markers (memory_markers.h): the fading of a remembered instance by age and uncertainty,
// and the markers drawn for present and gone instances.
#include "view_direction_classification/ros/memory_markers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace vdc {
namespace {

using view_direction_classification::ObjectInstance;

TEST(MemoryAlpha, FreshAndSharpIsOpaqueAndEverythingStaysVisible) {
  EXPECT_FLOAT_EQ(memoryAlpha(0.0, 0.0, 60.0), 1.0f);
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (double age : {-5.0, 0.0, 1.0, 60.0, 1e6, inf, nan}) {
    for (double cone : {-1.0, 0.0, 10.0, 90.0, 180.0, 400.0, inf, nan}) {
      const float alpha = memoryAlpha(age, cone, 60.0);
      EXPECT_GE(alpha, kMemoryMinAlpha) << age << " s, " << cone << " deg";
      EXPECT_LE(alpha, 1.0f) << age << " s, " << cone << " deg";
    }
  }
  EXPECT_FLOAT_EQ(memoryAlpha(inf, 0.0, 60.0), kMemoryMinAlpha);
  EXPECT_FLOAT_EQ(memoryAlpha(nan, 0.0, 60.0), kMemoryMinAlpha);
  EXPECT_FLOAT_EQ(memoryAlpha(-5.0, 0.0, 60.0), 1.0f);  // clocks apart: as if seen now
}

TEST(MemoryAlpha, FadesMonotonicallyWithAgeAndCone) {
  for (double cone : {0.0, 30.0, 180.0}) {
    float previous = 2.0f;
    for (double age = 0.0; age < 1000.0; age += 7.5) {
      const float alpha = memoryAlpha(age, cone, 60.0);
      EXPECT_LE(alpha, previous) << age << " s, " << cone << " deg";
      previous = alpha;
    }
    EXPECT_LT(memoryAlpha(120.0, cone, 60.0), memoryAlpha(0.0, cone, 60.0));
  }
  for (double age : {0.0, 30.0, 300.0}) {
    float previous = 2.0f;
    for (double cone = 0.0; cone <= 180.0; cone += 5.0) {
      const float alpha = memoryAlpha(age, cone, 60.0);
      EXPECT_LE(alpha, previous) << age << " s, " << cone << " deg";
      previous = alpha;
    }
    EXPECT_LT(memoryAlpha(age, 180.0, 60.0), memoryAlpha(age, 0.0, 60.0));
  }
}

TEST(MemoryAlpha, FadeAgeHalvesWhatLiesAboveTheFloor) {
  const float fresh = memoryAlpha(0.0, 0.0, 60.0) - kMemoryMinAlpha;
  EXPECT_NEAR(memoryAlpha(60.0, 0.0, 60.0) - kMemoryMinAlpha, 0.5f * fresh, 1e-6);
  EXPECT_NEAR(memoryAlpha(0.0, 180.0, 60.0) - kMemoryMinAlpha, 0.5f * fresh, 1e-6);
  EXPECT_GT(memoryAlpha(60.0, 0.0, 600.0), memoryAlpha(60.0, 0.0, 60.0));  // slower fade
}

ObjectInstance instanceAt(const std::string& name, double x, double last_seen, bool gone) {
  ObjectInstance instance;
  instance.name = name;
  instance.identity_probability = 0.93;
  instance.pose.pose.position.x = x;
  instance.pose.pose.orientation.w = 1.0;
  instance.cone90_deg = 10.0;
  instance.last_seen = ros::Time(last_seen);
  instance.state = gone ? ObjectInstance::GONE : ObjectInstance::PRESENT;
  return instance;
}

TEST(MemoryMarkers, EveryInstanceAtItsPlaceFadedByAgeGoneOnesGreyAndLabelled) {
  std_msgs::Header header;
  header.frame_id = "world";
  const std::vector<ObjectInstance> instances = {instanceAt("mug_1", 1.0, 100.0, false),
                                                 instanceAt("bowl_1", 2.0, 10.0, true)};
  const auto markers = makeMemoryMarkers(header, instances, ros::Time(100.0), 60.0, 0.05);
  ASSERT_EQ(markers.markers.size(), 5u);
  EXPECT_EQ(markers.markers[0].action, visualization_msgs::Marker::DELETEALL);
  const auto& mug = markers.markers[1];
  const auto& mug_label = markers.markers[2];
  const auto& bowl = markers.markers[3];
  const auto& bowl_label = markers.markers[4];
  EXPECT_EQ(mug.type, visualization_msgs::Marker::SPHERE);
  EXPECT_EQ(mug.ns, "mug_1");
  EXPECT_EQ(mug.header.frame_id, "world");
  EXPECT_DOUBLE_EQ(mug.pose.position.x, 1.0);
  EXPECT_DOUBLE_EQ(bowl.pose.position.x, 2.0);
  EXPECT_DOUBLE_EQ(mug.scale.x, 0.05);
  EXPECT_FLOAT_EQ(mug.color.a, memoryAlpha(0.0, 10.0, 60.0));
  EXPECT_FLOAT_EQ(bowl.color.a, memoryAlpha(90.0, 10.0, 60.0));
  EXPECT_LT(bowl.color.a, mug.color.a);
  EXPECT_EQ(bowl.color.r, bowl.color.b);  // grey
  EXPECT_NE(mug.color.r, mug.color.b);
  EXPECT_EQ(mug_label.type, visualization_msgs::Marker::TEXT_VIEW_FACING);
  EXPECT_GT(mug_label.pose.position.z, mug.pose.position.z);
  EXPECT_EQ(mug_label.text, "mug_1 (0.93), 0 s ago");
  EXPECT_EQ(bowl_label.text, "bowl_1 (0.93) GONE, 90 s ago");
  EXPECT_EQ(bowl_label.ns, "bowl_1");
  EXPECT_EQ(bowl_label.id, 1);
}

TEST(MemoryMarkers, NeverSeenIsFaintestAndNoInstancesOnlyClears) {
  std_msgs::Header header;
  ObjectInstance unseen = instanceAt("mug_1", 0.0, 0.0, false);
  unseen.last_seen = ros::Time();
  const auto markers = makeMemoryMarkers(header, {unseen}, ros::Time(50.0), 60.0, 0.05);
  ASSERT_EQ(markers.markers.size(), 3u);
  EXPECT_FLOAT_EQ(markers.markers[1].color.a, kMemoryMinAlpha);
  EXPECT_EQ(markers.markers[2].text, "mug_1 (0.93), never seen");
  EXPECT_EQ(makeMemoryMarkers(header, {}, ros::Time(50.0), 60.0, 0.05).markers.size(), 1u);
}

}  // namespace
}  // namespace vdc
