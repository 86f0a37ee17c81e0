#pragma once

#include <ros/time.h>
#include <std_msgs/Header.h>
#include <view_direction_classification/ObjectInstance.h>
#include <visualization_msgs/MarkerArray.h>

#include <vector>

namespace vdc {

// The faintest a remembered instance is drawn: however old and uncertain, it stays visible.
inline constexpr float kMemoryMinAlpha = 0.15f;

// The opacity of a remembered instance's markers: 1 for one seen just now with a sharp belief,
// falling with the time since it was last seen (age_s: what lies above kMemoryMinAlpha halves
// every fade_age_s) and with its belief's 90 % cone (cone90_deg; 180, a uniform belief, halves
// it too): an old or vague memory is drawn faint, never below kMemoryMinAlpha. Monotone in both, in
// [kMemoryMinAlpha, 1]; a negative age (clocks apart) counts as 0, an unknown (NaN or infinite) age
// or cone as the oldest or widest. fade_age_s > 0.
float memoryAlpha(double age_s, double cone90_deg, double fade_age_s);

// rviz markers of every remembered instance at its believed position (header.frame_id, the
// fixed frame), present or gone, also those out of view: a DELETEALL first (forgotten instances
// vanish), then per instance, namespace "<name>", a SPHERE (id 0, `size` across) and a
// TEXT_VIEW_FACING label above it (id 1: name, identity probability, age, "GONE" for a gone
// one), faded by memoryAlpha with its age at `now`. Present instances are blue, gone ones grey.
visualization_msgs::MarkerArray makeMemoryMarkers(
    const std_msgs::Header& header,
    const std::vector<view_direction_classification::ObjectInstance>& instances,
    const ros::Time& now, double fade_age_s, double size);

}  // namespace vdc
