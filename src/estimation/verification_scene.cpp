#include "view_direction_classification/estimation/verification_scene.h"

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

}  // namespace vdc
