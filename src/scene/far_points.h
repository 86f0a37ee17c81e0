#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

namespace vdc::scene {

// [m] A depth camera measures metres. A finite coordinate beyond this is a corrupt point, not a
// measurement, and it would overflow the voxel keys and the k-d trees' splits (the fuzz target
// found it): it counts as no point.
constexpr float kMaxCoordinate = 1000.0f;

// Whether the point is finite but beyond kMaxCoordinate.
bool isFar(const pcl::PointXYZ& p);

// The cloud with its far points made NaN: the same size and layout, so indices stay valid.
pcl::PointCloud<pcl::PointXYZ> withoutFarPoints(const pcl::PointCloud<pcl::PointXYZ>& cloud);

}  // namespace vdc::scene
