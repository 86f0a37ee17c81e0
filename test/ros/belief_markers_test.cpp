#include "view_direction_classification/ros/belief_markers.h"

#include <gtest/gtest.h>

#include "view_direction_classification/common/quaternion.h"

namespace vdc {
namespace {

Eigen::Vector3d toEigen(const geometry_msgs::Point& p) { return Eigen::Vector3d(p.x, p.y, p.z); }

std_msgs::Header worldHeader() {
  std_msgs::Header header;
  header.frame_id = "world";
  return header;
}

TEST(BeliefMarkers, MapAxesAreRedGreenBlueArrowsAlongTheRotatedAxes) {
  const Eigen::Vector3d position(1.0, -2.0, 0.5);
  const Eigen::Vector4d q = quaternionFromAxisAngle(Eigen::Vector3d(0.3, 1.0, -0.2), 1.1);
  const visualization_msgs::MarkerArray markers =
      makeBeliefMarkers(worldHeader(), "est", position, q, {}, 0.1);
  ASSERT_EQ(markers.markers.size(), 3u);  // no samples: no line list
  const Eigen::Matrix3d rotation = quaternionToRotationMatrix(q);
  for (int axis = 0; axis < 3; ++axis) {
    const visualization_msgs::Marker& arrow = markers.markers[axis];
    EXPECT_EQ(arrow.type, visualization_msgs::Marker::ARROW);
    EXPECT_EQ(arrow.ns, "est/map");
    EXPECT_EQ(arrow.id, axis);
    EXPECT_EQ(arrow.header.frame_id, "world");
    ASSERT_EQ(arrow.points.size(), 2u);
    EXPECT_LT((toEigen(arrow.points[0]) - position).norm(), 1e-12);
    EXPECT_LT((toEigen(arrow.points[1]) - position - 0.1 * rotation.col(axis)).norm(), 1e-12);
    EXPECT_EQ(arrow.color.r, axis == 0 ? 1.0f : 0.0f);
    EXPECT_EQ(arrow.color.g, axis == 1 ? 1.0f : 0.0f);
    EXPECT_EQ(arrow.color.b, axis == 2 ? 1.0f : 0.0f);
    EXPECT_EQ(arrow.color.a, 1.0f);
  }
}

TEST(BeliefMarkers, EachSampleIsATranslucentTriadOfThreeLines) {
  const std::vector<Eigen::Vector4d> samples = {
      Eigen::Vector4d(1, 0, 0, 0), quaternionFromAxisAngle(Eigen::Vector3d::UnitZ(), M_PI / 2)};
  const visualization_msgs::MarkerArray markers = makeBeliefMarkers(
      worldHeader(), "est", Eigen::Vector3d::Zero(), Eigen::Vector4d(1, 0, 0, 0), samples, 0.1);
  ASSERT_EQ(markers.markers.size(), 4u);
  const visualization_msgs::Marker& lines = markers.markers[3];
  EXPECT_EQ(lines.type, visualization_msgs::Marker::LINE_LIST);
  EXPECT_EQ(lines.ns, "est/samples");
  ASSERT_EQ(lines.points.size(), 12u);  // 2 samples x 3 axes x 2 end points
  ASSERT_EQ(lines.colors.size(), 12u);
  for (const auto& colour : lines.colors) EXPECT_LT(colour.a, 1.0f);
  // The second sample turns x onto y: its red line ends at 0.8 * length along +y.
  EXPECT_LT((toEigen(lines.points[7]) - Eigen::Vector3d(0, 0.08, 0)).norm(), 1e-12);
  EXPECT_EQ(lines.colors[7].r, 1.0f);
}

TEST(BeliefMarkers, ClearMarkersDeleteEverything) {
  const visualization_msgs::MarkerArray markers = makeClearMarkers(worldHeader());
  ASSERT_EQ(markers.markers.size(), 1u);
  EXPECT_EQ(markers.markers[0].action, visualization_msgs::Marker::DELETEALL);
}

}  // namespace
}  // namespace vdc
