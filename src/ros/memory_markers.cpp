#include "view_direction_classification/ros/memory_markers.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "view_direction_classification/ros/belief_markers.h"

namespace vdc {
namespace {

using ObjectInstanceMsg = view_direction_classification::ObjectInstance;

// The label's height above the sphere's centre, in sphere sizes, and its text height [m].
constexpr double kLabelAbove = 1.2;
constexpr double kLabelHeight = 0.025;

// How long ago, as a person reads it; "never seen" for an instance without a last_seen.
std::string ageText(double age_s) {
  if (!std::isfinite(age_s)) return "never seen";
  std::ostringstream text;
  const double age = std::max(0.0, age_s);
  if (age < 120.0) {
    text << static_cast<long>(age) << " s ago";
  } else if (age < 7200.0) {
    text << static_cast<long>(age / 60.0) << " min ago";
  } else {
    text << static_cast<long>(age / 3600.0) << " h ago";
  }
  return text.str();
}

std_msgs::ColorRGBA colour(bool gone, float alpha) {
  std_msgs::ColorRGBA c;
  if (gone) {
    c.r = c.g = c.b = 0.55f;
  } else {
    c.r = 0.15f;
    c.g = 0.55f;
    c.b = 1.0f;
  }
  c.a = alpha;
  return c;
}

visualization_msgs::Marker baseMarker(const std_msgs::Header& header,
                                      const ObjectInstanceMsg& instance, int id, int type) {
  visualization_msgs::Marker marker;
  marker.header = header;
  marker.ns = instance.name;
  marker.id = id;
  marker.type = type;
  marker.action = visualization_msgs::Marker::ADD;
  marker.pose.position = instance.pose.pose.position;
  marker.pose.orientation.w = 1.0;
  return marker;
}

std::string labelText(const ObjectInstanceMsg& instance, double age_s) {
  std::ostringstream text;
  text.precision(2);
  text << instance.name << " (" << instance.identity_probability << ")";
  if (instance.state == ObjectInstanceMsg::GONE) text << " GONE";
  text << ", " << ageText(age_s);
  return text.str();
}

}  // namespace

float memoryAlpha(double age_s, double cone90_deg, double fade_age_s) {
  // NaN compares false: an unknown age or cone fades fully.
  const double age = age_s >= 0.0 ? age_s : (std::isnan(age_s) ? HUGE_VAL : 0.0);
  const double cone =
      cone90_deg >= 0.0 ? std::min(cone90_deg, 180.0) : (std::isnan(cone90_deg) ? 180.0 : 0.0);
  const double by_age = std::exp2(-age / fade_age_s);
  const double by_cone = 1.0 - 0.5 * cone / 180.0;
  const double alpha = kMemoryMinAlpha + (1.0 - kMemoryMinAlpha) * by_age * by_cone;
  return static_cast<float>(std::clamp(alpha, double(kMemoryMinAlpha), 1.0));
}

visualization_msgs::MarkerArray makeMemoryMarkers(const std_msgs::Header& header,
                                                  const std::vector<ObjectInstanceMsg>& instances,
                                                  const ros::Time& now, double fade_age_s,
                                                  double size) {
  visualization_msgs::MarkerArray markers = makeClearMarkers(header);
  for (const ObjectInstanceMsg& instance : instances) {
    const double age = instance.last_seen.isZero() ? HUGE_VAL : (now - instance.last_seen).toSec();
    const bool gone = instance.state == ObjectInstanceMsg::GONE;
    const float alpha = memoryAlpha(age, instance.cone90_deg, fade_age_s);
    visualization_msgs::Marker sphere =
        baseMarker(header, instance, 0, visualization_msgs::Marker::SPHERE);
    sphere.scale.x = sphere.scale.y = sphere.scale.z = size;
    sphere.color = colour(gone, alpha);
    markers.markers.push_back(sphere);
    visualization_msgs::Marker label =
        baseMarker(header, instance, 1, visualization_msgs::Marker::TEXT_VIEW_FACING);
    label.pose.position.z += kLabelAbove * size;
    label.scale.z = kLabelHeight;
    // The text fades less than the sphere: an old memory's name must stay readable.
    label.color = colour(gone, 0.4f + 0.6f * alpha);
    if (!gone) label.color.r = label.color.g = label.color.b = 1.0f;
    label.text = labelText(instance, age);
    markers.markers.push_back(label);
  }
  return markers;
}

}  // namespace vdc
