#include "seen_through.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <vector>

namespace vdc {
namespace {

constexpr float kRayRadius = 0.004f;  // [m] at the point's depth, as verification's neighbours

// The depth of the nearest point of `points` on the ray (NaN: none within the ray radius).
float depthOnRay(const pcl::PointCloud<pcl::PointXYZ>::ConstPtr& points,
                 const std::shared_ptr<const NearestPoints>& rays, const Eigen::Vector3f& point) {
  if (!points || !rays) return std::numeric_limits<float>::quiet_NaN();
  const float radius = kRayRadius / point.z();
  std::vector<int> index;
  std::vector<float> squared;
  rays->search({Eigen::Vector3f(point.x() / point.z(), point.y() / point.z(), 0.0f)}, &index,
               &squared, radius);
  if (index[0] < 0 || squared[0] > radius * radius) return std::numeric_limits<float>::quiet_NaN();
  return (*points)[index[0]].z;
}

}  // namespace

bool seenThrough(const SceneDepth& scene, const Eigen::Vector3f& point, double tolerance) {
  if (!point.allFinite() || !(point.z() > 0.0f)) return false;
  const float occluder = depthOnRay(scene.occluders, scene.occluder_rays, point);
  const float support = depthOnRay(scene.supports, scene.support_rays, point);
  float first = std::numeric_limits<float>::quiet_NaN();
  if (!std::isnan(occluder)) first = occluder;
  if (!std::isnan(support) && (std::isnan(first) || support < first)) first = support;
  return !std::isnan(first) && first > point.z() + tolerance;
}

}  // namespace vdc
