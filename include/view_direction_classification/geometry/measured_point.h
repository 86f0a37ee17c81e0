#pragma once

// Which points of a camera's cloud count as measurements (the estimator's segmentation and
// tracking, the refiner's views).

#include <pcl/point_types.h>

#include <cmath>

namespace vdc {

// No depth sensor measures beyond this from its cloud's origin [m]. Farther points are a
// driver's garbage: near a float's maximum, kd-trees that split a range at (min + max) / 2
// overflow and FLANN recurses without end (a crash, not an exception).
constexpr float kMaxMeasuredRange = 1e4f;

// Finite and within kMaxMeasuredRange on every axis; NaN marks a pixel without depth.
inline bool isMeasuredPoint(const pcl::PointXYZ& p) {
  return std::abs(p.x) <= kMaxMeasuredRange && std::abs(p.y) <= kMaxMeasuredRange &&
         std::abs(p.z) <= kMaxMeasuredRange;  // false for NaN
}

}  // namespace vdc
