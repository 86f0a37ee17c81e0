#include "view_direction_classification/recognition/instance_explanation.h"

namespace vdc {

InstanceExplanation::InstanceExplanation(const ModelBundle& model)
    : surface_(std::make_unique<const NearestPoints>(model.surface_points)) {}

double InstanceExplanation::explainedFraction(const std::vector<Eigen::Vector3f>& points_world,
                                              const Eigen::Isometry3d& world_from_object,
                                              double tolerance) const {
  if (points_world.empty()) return 0.0;
  const Eigen::Isometry3f object_from_world = world_from_object.inverse().cast<float>();
  std::vector<Eigen::Vector3f> queries;
  queries.reserve(points_world.size());
  for (const Eigen::Vector3f& p : points_world) queries.push_back(object_from_world * p);
  std::vector<int> indices;
  std::vector<float> squared;
  surface_->search(queries, &indices, &squared, tolerance);
  int explained = 0;
  for (int index : indices) explained += index >= 0 ? 1 : 0;
  return static_cast<double>(explained) / points_world.size();
}

bool InstanceExplanation::explainsPart(const std::vector<Eigen::Vector3f>& points_world,
                                       const Eigen::Isometry3d& world_from_object, double tolerance,
                                       double min_fraction) const {
  return explainedFraction(points_world, world_from_object, tolerance) >= min_fraction;
}

}  // namespace vdc
