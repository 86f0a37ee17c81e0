#include "far_points.h"

#include <cmath>
#include <limits>

namespace vdc::scene {

bool isFar(const pcl::PointXYZ& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) &&
         p.getVector3fMap().cwiseAbs().maxCoeff() > kMaxCoordinate;
}

pcl::PointCloud<pcl::PointXYZ> withoutFarPoints(const pcl::PointCloud<pcl::PointXYZ>& cloud) {
  pcl::PointCloud<pcl::PointXYZ> measured = cloud;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (auto& p : measured.points) {
    if (isFar(p)) p.x = p.y = p.z = nan;
  }
  measured.is_dense = false;
  return measured;
}

}  // namespace vdc::scene
