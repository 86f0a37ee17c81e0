#include "view_direction_classification/scene/label_segmentation.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>

#include "candidate_shape.h"
#include "far_points.h"
#include "support_planes.h"

namespace vdc {
namespace {

// One label's measured points, before they become a candidate.
struct LabelPoints {
  std::uint32_t value = 0;
  std::vector<int> indices;  // ascending
  int support = -1;
};

bool finite(const pcl::PointXYZ& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// Whether the label image holds one label per point of the cloud, the cloud's width x height.
bool sameShape(const pcl::PointCloud<pcl::PointXYZ>& cloud, const LabelImage& labels) {
  const std::size_t pixels = std::size_t(cloud.width) * cloud.height;
  return labels.width >= 0 && labels.height >= 0 &&
         static_cast<std::size_t>(labels.width) == cloud.width &&
         static_cast<std::size_t>(labels.height) == cloud.height && cloud.size() == pixels &&
         labels.labels.size() == pixels;
}

// Each non-zero label's measured points (in index order, so ascending), by label value.
std::vector<LabelPoints> pointsPerLabel(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                        const LabelImage& labels) {
  std::map<std::uint32_t, std::vector<int>> by_value;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (labels.labels[i] == 0 || !finite(cloud[i])) continue;
    by_value[labels.labels[i]].push_back(static_cast<int>(i));
  }
  std::vector<LabelPoints> result;
  result.reserve(by_value.size());
  for (auto& [value, indices] : by_value) result.push_back({value, std::move(indices)});
  return result;
}

// The support planes, found as segmentScene finds them (image neighbourhoods in an organised
// cloud large enough, RANSAC otherwise): the verification scene leaves their points out, and a
// mask's points on them are the table's.
std::vector<SupportPlane> supportPlanes(const pcl::PointCloud<pcl::PointXYZ>& cloud,
                                        const std::vector<int>& measured,
                                        const SceneSegmentationParameters& parameters,
                                        bool organised) {
  if (parameters.max_support_planes == 0) return {};
  if (!organised) return scene::findRansacSupportPlanes(cloud, measured, parameters);
  // PCL's interfaces take a shared pointer: this one borrows the caller's cloud.
  const pcl::PointCloud<pcl::PointXYZ>::ConstPtr view(&cloud,
                                                      [](const pcl::PointCloud<pcl::PointXYZ>*) {});
  return scene::findOrganisedSupportPlanes(view, parameters);
}

// Leaves out a label's points that stand on no support (on a plane, below it, too high above it)
// and finds the support most of the rest stand on.
void keepStanding(const std::vector<int>& standing, LabelPoints* label) {
  std::vector<int>& indices = label->indices;
  indices.erase(
      std::remove_if(
          indices.begin(), indices.end(),
          [&](int i) { return standing[static_cast<std::size_t>(i)] == scene::kNotStanding; }),
      indices.end());
  label->support = scene::supportOf(indices, standing);
}

bool largerFirst(const LabelPoints& a, const LabelPoints& b) {
  // Ties by the label value, so that the order depends on the image alone.
  if (a.indices.size() != b.indices.size()) return a.indices.size() > b.indices.size();
  return a.value < b.value;
}

// Ignores the labels with fewer than min_cluster_points and keeps the max_candidates largest,
// noting both.
void capLabels(std::vector<LabelPoints>* labels, const SceneSegmentationParameters& parameters,
               SceneSegments* result) {
  const std::size_t before = labels->size();
  labels->erase(std::remove_if(labels->begin(), labels->end(),
                               [&](const LabelPoints& label) {
                                 return label.indices.size() <
                                        static_cast<std::size_t>(parameters.min_cluster_points);
                               }),
                labels->end());
  if (const std::size_t small = before - labels->size(); small > 0) {
    result->note += std::to_string(small) + " label(s) with fewer than " +
                    std::to_string(parameters.min_cluster_points) +
                    " object points ignored (min_cluster_points); ";
  }
  std::sort(labels->begin(), labels->end(), largerFirst);
  if (labels->size() > static_cast<std::size_t>(parameters.max_candidates)) {
    const std::size_t excess = labels->size() - static_cast<std::size_t>(parameters.max_candidates);
    labels->resize(static_cast<std::size_t>(parameters.max_candidates));
    result->dropped_clusters += static_cast<int>(excess);
    result->note += std::to_string(excess) + " smallest label(s) dropped (max_candidates " +
                    std::to_string(parameters.max_candidates) + "); ";
  }
}

}  // namespace

std::int64_t labelClass(std::uint32_t value, int class_divisor) {
  return static_cast<std::int64_t>(value) / std::max(class_divisor, 1);
}

SceneSegments segmentLabels(const pcl::PointCloud<pcl::PointXYZ>& cloud, const LabelImage& labels,
                            const SceneSegmentationParameters& parameters) {
  checkSceneSegmentationParameters(parameters);
  SceneSegments result;
  if (!sameShape(cloud, labels)) {
    result.note = "the label image (" + std::to_string(labels.width) + " x " +
                  std::to_string(labels.height) + ", " + std::to_string(labels.labels.size()) +
                  " labels) is not the cloud's size (" + std::to_string(cloud.width) + " x " +
                  std::to_string(cloud.height) + ")";
    return result;
  }
  // Corrupt far points count as no points here too (the plane search would overflow on them).
  if (std::any_of(cloud.points.begin(), cloud.points.end(), scene::isFar)) {
    return segmentLabels(scene::withoutFarPoints(cloud), labels, parameters);
  }
  std::vector<int> measured;
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    if (finite(cloud[i])) measured.push_back(static_cast<int>(i));
  }
  result.organised = cloud.isOrganized() && cloud.width >= scene::kMinOrganisedSide &&
                     cloud.height >= scene::kMinOrganisedSide;
  std::vector<LabelPoints> per_label = pointsPerLabel(cloud, labels);
  // The plane search is most of the cost: not for a frame without a label large enough.
  const bool any_large = std::any_of(per_label.begin(), per_label.end(), [&](const auto& label) {
    return label.indices.size() >= static_cast<std::size_t>(parameters.min_cluster_points);
  });
  if (any_large) {
    result.planes = supportPlanes(cloud, measured, parameters, result.organised);
    const std::vector<int> standing = scene::standingOn(cloud, measured, result.planes, parameters);
    for (LabelPoints& label : per_label) keepStanding(standing, &label);
  }
  capLabels(&per_label, parameters, &result);
  for (LabelPoints& label : per_label) {
    SceneCandidate candidate;
    candidate.indices = std::move(label.indices);
    scene::describeShape(cloud, &candidate);
    candidate.support = label.support;
    candidate.class_id = labelClass(label.value, parameters.label_class_divisor);
    result.candidates.push_back(std::move(candidate));
  }
  if (result.candidates.empty()) {
    result.note += "no label of at least " + std::to_string(parameters.min_cluster_points) +
                   " object points in the label image";
  }
  return result;
}

}  // namespace vdc
