#include "view_direction_classification/ros/belief_markers.h"

#include <tf2_eigen/tf2_eigen.h>

#include "view_direction_classification/common/quaternion.h"

namespace vdc {
namespace {

std_msgs::ColorRGBA axisColour(int axis, float alpha) {
  std_msgs::ColorRGBA colour;
  colour.r = axis == 0 ? 1.0f : 0.0f;
  colour.g = axis == 1 ? 1.0f : 0.0f;
  colour.b = axis == 2 ? 1.0f : 0.0f;
  colour.a = alpha;
  return colour;
}

visualization_msgs::Marker makeMarker(const std_msgs::Header& header, const std::string& ns, int id,
                                      int type) {
  visualization_msgs::Marker marker;
  marker.header = header;
  marker.ns = ns;
  marker.id = id;
  marker.type = type;
  marker.action = visualization_msgs::Marker::ADD;
  marker.pose.orientation.w = 1.0;  // points are given in header.frame_id directly
  return marker;
}

}  // namespace

visualization_msgs::MarkerArray makeBeliefMarkers(const std_msgs::Header& header,
                                                  const std::string& ns,
                                                  const Eigen::Vector3d& position,
                                                  const Eigen::Vector4d& map_orientation,
                                                  const std::vector<Eigen::Vector4d>& samples,
                                                  double length) {
  visualization_msgs::MarkerArray markers;
  const Eigen::Matrix3d map_rotation = quaternionToRotationMatrix(map_orientation);
  for (int axis = 0; axis < 3; ++axis) {
    visualization_msgs::Marker arrow =
        makeMarker(header, ns + "/map", axis, visualization_msgs::Marker::ARROW);
    arrow.points.push_back(tf2::toMsg(position));
    arrow.points.push_back(tf2::toMsg(Eigen::Vector3d(position + length * map_rotation.col(axis))));
    arrow.scale.x = 0.08 * length;  // shaft diameter
    arrow.scale.y = 0.16 * length;  // head diameter
    arrow.scale.z = 0.25 * length;  // head length
    arrow.color = axisColour(axis, 1.0f);
    markers.markers.push_back(arrow);
  }
  if (!samples.empty()) {
    visualization_msgs::Marker lines =
        makeMarker(header, ns + "/samples", 0, visualization_msgs::Marker::LINE_LIST);
    lines.scale.x = 0.01 * length;  // line width
    lines.color = axisColour(0, 0.3f);
    const double sample_length = 0.8 * length;
    for (const Eigen::Vector4d& q : samples) {
      const Eigen::Matrix3d rotation = quaternionToRotationMatrix(q.normalized());
      for (int axis = 0; axis < 3; ++axis) {
        lines.points.push_back(tf2::toMsg(position));
        lines.points.push_back(
            tf2::toMsg(Eigen::Vector3d(position + sample_length * rotation.col(axis))));
        lines.colors.push_back(axisColour(axis, 0.3f));
        lines.colors.push_back(axisColour(axis, 0.3f));
      }
    }
    markers.markers.push_back(lines);
  }
  return markers;
}

visualization_msgs::MarkerArray makeClearMarkers(const std_msgs::Header& header) {
  visualization_msgs::MarkerArray markers;
  visualization_msgs::Marker clear;
  clear.header = header;
  clear.action = visualization_msgs::Marker::DELETEALL;
  markers.markers.push_back(clear);
  return markers;
}

}  // namespace vdc
