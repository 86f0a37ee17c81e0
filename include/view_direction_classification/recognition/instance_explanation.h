#pragma once

#include <Eigen/Geometry>

#include <memory>
#include <vector>

#include "view_direction_classification/refinement/nearest_points.h"
#include "view_direction_classification/training/model_bundle.h"

namespace vdc {

// How much of a candidate a known instance's pose already explains. Segmentation splits an
// object where its surface is concave (a mug's handle from its body: section 13); the piece is
// no object of its own but part of an instance, and identifying it alone would place a second
// model behind the first, where the whole-scene verification cannot see it is wrong.
class InstanceExplanation {
 public:
  // Indexes the model's surface set (object frame).
  explicit InstanceExplanation(const ModelBundle& model);

  // The fraction of `points_world` (fixed frame) within `tolerance` [m] of the model's surface
  // placed at world_from_object. 0 for no points.
  double explainedFraction(const std::vector<Eigen::Vector3f>& points_world,
                           const Eigen::Isometry3d& world_from_object, double tolerance) const;

  // Per point of `points_world`: whether it lies within `tolerance` [m] of the placed surface
  // and, with normals_world (unit, one per point, facing the camera; a non-finite one is not
  // judged), faces the way the nearest sample does (their cosine at least min_normal_cosine): a
  // box's face pressed against a mug lies within millimetres of the mug's side, facing it.
  std::vector<bool> explainedPoints(const std::vector<Eigen::Vector3f>& points_world,
                                    const Eigen::Isometry3d& world_from_object, double tolerance,
                                    const std::vector<Eigen::Vector3f>* normals_world = nullptr,
                                    double min_normal_cosine = 0.5) const;

  // Whether the model placed at world_from_object explains `points_world` as one of its parts:
  // at least min_fraction of them within tolerance [m] of its surface.
  bool explainsPart(const std::vector<Eigen::Vector3f>& points_world,
                    const Eigen::Isometry3d& world_from_object, double tolerance,
                    double min_fraction) const;

 private:
  std::unique_ptr<const NearestPoints> surface_;
  std::vector<Eigen::Vector3f> normals_;  // the samples' outward normals (object frame)
};

}  // namespace vdc
