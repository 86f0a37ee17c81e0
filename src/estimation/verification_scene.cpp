#include "view_direction_classification/estimation/verification_scene.h"

#include <algorithm>
#include <cmath>

namespace vdc {

namespace {

// The table's points are many and flat, and the verifier needs only its depth near each ray: in
// an organized cloud every second row and column keep a point within the verifier's ray radius
// (a few pixels at any depth a camera sees a table) for a quarter of the cost of indexing them.
bool keptSupportPoint(const pcl::PointCloud<pcl::PointXYZ>& cloud, std::size_t i) {
  if (cloud.height <= 1 || cloud.width == 0) return true;
  return (i % cloud.width) % 2 == 0 && (i / cloud.width) % 2 == 0;
}

}  // namespace

SceneDepth verificationScene(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                             const ObjectSegment& object,
                             const SegmentationParameters& segmentation) {
  if (segmentation.mode == SegmentationMode::kNone) return {};
  auto occluders = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  auto table = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  occluders->reserve(cloud.size());
  const float plane_distance = static_cast<float>(segmentation.plane_distance);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const auto& p = cloud[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) continue;
    if (!object.table) {
      occluders->push_back(p);
      continue;
    }
    // The table's normal points towards the camera: what stands above it can hide the object;
    // what lies below it (the floor past its edge) is left out.
    const float height = object.table->head<3>().cast<float>().dot(p.getVector3fMap()) +
                         static_cast<float>((*object.table)[3]);
    if (height > plane_distance) {
      occluders->push_back(p);
    } else if (height >= -plane_distance && keptSupportPoint(cloud, i)) {
      table->push_back(p);
    }
  }
  SceneDepth scene;
  if (occluders->size() > object.points.size()) scene.occluders = occluders;
  if (!table->empty()) scene.supports = table;
  scene.support_plane = object.table;
  return scene;
}

SceneDepth verificationScene(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                             const std::vector<Eigen::Vector4d>& supports, double plane_distance) {
  auto occluders = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  auto on_supports = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  occluders->reserve(cloud.size());
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    const auto& p = cloud[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) continue;
    const Eigen::Vector3d x = p.getVector3fMap().cast<double>();
    // The normals point towards the camera: what stands above a plane is kept as an occluder.
    const bool on_a_support = std::any_of(supports.begin(), supports.end(), [&](const auto& n) {
      return std::abs(n.template head<3>().dot(x) + n[3]) <= plane_distance;
    });
    if (!on_a_support) {
      occluders->push_back(p);
    } else if (keptSupportPoint(cloud, i)) {
      on_supports->push_back(p);
    }
  }
  SceneDepth scene;
  scene.occluders = occluders;
  scene.supports = on_supports;
  return scene;
}

}  // namespace vdc
