#pragma once

#include <pcl/point_types.h>

namespace vdc::scene {

// A tolerance [m] of `near` close to the camera and near + growth * z^2 at depth z
// (SceneSegmentationParameters::depth_tolerance_growth says why).
struct DepthTolerance {
  double near = 0.0;
  double growth = 0.0;
};

// The tolerance at the point's depth. The camera looks along +z or -z (PCL's scenes use both):
// only z^2 counts.
inline double toleranceAt(const DepthTolerance& tolerance, const pcl::PointXYZ& p) {
  const double z = p.z;
  return tolerance.near + tolerance.growth * z * z;
}

}  // namespace vdc::scene
