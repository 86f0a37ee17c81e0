#include "view_direction_classification/estimation/verification_scene.h"

#include <algorithm>
#include <cmath>

namespace vdc {

pcl::PointCloud<pcl::PointXYZ>::ConstPtr verificationScene(
    const pcl::PointCloud<pcl::PointXYZ>& cloud, const ObjectSegment& object,
    const SegmentationParameters& segmentation) {
  if (segmentation.mode == SegmentationMode::kNone) return nullptr;
  auto scene = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  scene->reserve(cloud.size());
  for (const auto& p : cloud.points) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) continue;
    // The table's normal points towards the camera: keep what stands above it.
    if (object.table && object.table->head<3>().cast<float>().dot(p.getVector3fMap()) +
                                static_cast<float>((*object.table)[3]) <=
                            static_cast<float>(segmentation.plane_distance)) {
      continue;
    }
    scene->push_back(p);
  }
  if (scene->size() <= object.points.size()) return nullptr;
  return scene;
}

pcl::PointCloud<pcl::PointXYZ>::ConstPtr verificationScene(
    const pcl::PointCloud<pcl::PointXYZ>& cloud, const std::vector<Eigen::Vector4d>& supports,
    double plane_distance) {
  auto scene = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>>();
  scene->reserve(cloud.size());
  for (const auto& p : cloud.points) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) continue;
    const Eigen::Vector3d x = p.getVector3fMap().cast<double>();
    const bool on_a_support = std::any_of(supports.begin(), supports.end(), [&](const auto& n) {
      return std::abs(n.template head<3>().dot(x) + n[3]) <= plane_distance;
    });
    if (!on_a_support) scene->push_back(p);
  }
  return scene;
}

}  // namespace vdc
