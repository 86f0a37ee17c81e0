#pragma once

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstdint>

#include "view_direction_classification/scene/label_image.h"
#include "view_direction_classification/scene/scene_segmentation.h"

namespace vdc {

// The class of a label value: value / class_divisor (class_divisor >= 1; 1: the value itself).
std::int64_t labelClass(std::uint32_t value, int class_divisor);

// The object candidates of a label image instead of the geometric segmentation, in
// segmentScene's contract: one candidate per label (its class in class_id), indices ascending,
// shape described, most points first, the support planes found as segmentScene finds them.
// A label's points that are not measured (NaN, far), that lie on a support plane (a mask bleeding
// onto the table) or are no object of it (below it, higher than max_height_above_plane) are left
// out; a label with fewer than min_cluster_points left is ignored; beyond max_candidates the
// largest are kept and the rest counted in dropped_clusters. A label image that is not the
// cloud's size gives no candidates and a note. Uses label_class_divisor, min_cluster_points,
// max_candidates and the support-plane settings. Never throws for the content; throws vdc::Error
// for invalid parameters.
SceneSegments segmentLabels(const pcl::PointCloud<pcl::PointXYZ>& cloud, const LabelImage& labels,
                            const SceneSegmentationParameters& parameters);

}  // namespace vdc
